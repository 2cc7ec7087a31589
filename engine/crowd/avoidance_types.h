#pragma once
// The C++ view of shaders/crowd_types.h, with its layout checked against the GLSL blocks.
#include "shaders/crowd_types.h"

namespace throng::crowd {
using gpu_types::AdvancePush;
using gpu_types::GridPush;
using gpu_types::SteerPush;
using gpu_types::kScanBlock;

static_assert(sizeof(GridPush) == 32, "GridPush must match the GLSL push block");
static_assert(sizeof(SteerPush) == 80, "SteerPush must match the GLSL push block");
static_assert(sizeof(AdvancePush) == 16, "AdvancePush must match the GLSL push block");
}  // namespace throng::crowd
