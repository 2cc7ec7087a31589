#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_basic : require
// Root motion and the coverage LOD over the chunks the update-rate schedule listed
// (root_motion.glsl, update_rate.h).
#define THRONG_ROOT_MOTION_COVERAGE
#define THRONG_ROOT_MOTION_SCHEDULED
#include "root_motion.glsl"
