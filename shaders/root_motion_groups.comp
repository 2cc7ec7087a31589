#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Root motion of every clip set of a crowd in one dispatch (root_motion.glsl).
#define THRONG_ROOT_MOTION_GROUPS
#include "root_motion.glsl"
