#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Cache classify of every clip set of a crowd in one dispatch (cache_classify.glsl).
#define THRONG_CACHE_CLASSIFY_GROUPS
#include "cache_classify.glsl"
