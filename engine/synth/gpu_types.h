#pragma once
// The C++ view of shaders/shared_types.h, with its layout checked against std430.
#include "shaders/shared_types.h"

namespace throng::synth {
using gpu_types::CacheCounters;
using gpu_types::CachePush;
using gpu_types::JointMatrix;
using gpu_types::JointPoint;
using gpu_types::PosePush;
using gpu_types::RootMotionPrepPush;
using gpu_types::RootMotionPush;

static_assert(sizeof(JointMatrix) == 48, "JointMatrix must match the GLSL std430 layout");
static_assert(sizeof(JointPoint) == 16, "JointPoint must match the GLSL std430 layout");
static_assert(sizeof(RootMotionPush) == 80, "RootMotionPush must match the GLSL push block");
static_assert(sizeof(RootMotionPrepPush) == 32,
              "RootMotionPrepPush must match the GLSL push block");
static_assert(sizeof(PosePush) == 48, "PosePush must match the GLSL push block");
static_assert(sizeof(gpu_types::CacheCounters) == 32,
              "CacheCounters must match the GLSL std430 layout");
static_assert(sizeof(gpu_types::CachePush) == 48, "CachePush must match the GLSL push block");
}  // namespace throng::synth
