#pragma once
// The C++ view of shaders/crowd_types.h, with its layout checked against the GLSL blocks.
#include "shaders/crowd_types.h"

namespace throng::crowd {
using gpu_types::AdvancePush;
using gpu_types::GoalPush;
using gpu_types::GridPush;
using gpu_types::SteerPush;
using gpu_types::WallGridInfo;
using gpu_types::WallPush;

static_assert(sizeof(GridPush) == 32, "GridPush must match the GLSL push block");
static_assert(sizeof(SteerPush) == 128,
              "SteerPush must match the GLSL push block (at most 128 bytes)");
static_assert(sizeof(AdvancePush) == 16, "AdvancePush must match the GLSL push block");
static_assert(sizeof(WallGridInfo) == 32, "WallGridInfo must match the GLSL uniform block");
static_assert(sizeof(WallPush) == 32, "WallPush must match the GLSL push block");
static_assert(sizeof(GoalPush) == 16, "GoalPush must match the GLSL push block");
}  // namespace throng::crowd
