#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// The motion cache's classify under the update-rate LOD: only the chunks that moved this step
// (ClassifySchedulePush says why that is enough). CPU twin: synth::classifyScheduledCpu.
#define THRONG_CACHE_CLASSIFY_SCHEDULED
#include "update_rate.h"
#include "cache_classify.glsl"
