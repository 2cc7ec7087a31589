#version 450
#extension GL_GOOGLE_include_directive : require
// A near joint over a depth attachment that holds everything drawn before it.
#include "joint_fragment.glsl"
