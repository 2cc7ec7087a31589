#pragma once
// The C++ view of shaders/cloth_types.h, with its layout checked against std430/std140.
#include "shaders/cloth_types.h"

namespace throng::secondary {
static_assert(sizeof(gpu_types::ClothCharacter) == 16,
              "ClothCharacter must match the GLSL std430 layout");
static_assert(sizeof(gpu_types::ClothAdvancePush) == 32,
              "ClothAdvancePush must match the GLSL push block");
static_assert(sizeof(gpu_types::ClothLevel) == 16, "ClothLevel must match the GLSL std430 layout");
static_assert(sizeof(gpu_types::ClothView) == 64 + 6 * 16 + 5 * 16,
              "ClothView must match the GLSL std140 block");
static_assert(sizeof(gpu_types::ClothCounters) == 32,
              "ClothCounters must match the GLSL std430 layout");
static_assert(gpu_types::kClothLevelCount == 4,
              "ClothCounters::levelStates has one entry per level");
static_assert(sizeof(gpu_types::ClothArgsPush) == 16,
              "ClothArgsPush must match the GLSL push block");
static_assert(sizeof(gpu_types::ClothClassifyPush) == 16,
              "ClothClassifyPush must match the GLSL push block");
static_assert(sizeof(gpu_types::ClothMarkPush) == 16,
              "ClothMarkPush must match the GLSL push block");
static_assert(sizeof(gpu_types::ClothDecodePush) == 16,
              "ClothDecodePush must match the GLSL push block");
static_assert(sizeof(gpu_types::ClothDrawPush) == 16,
              "ClothDrawPush must match the GLSL push block");
static_assert(sizeof(gpu_types::ClothSplatPush) == 16,
              "ClothSplatPush must match the GLSL push block");
}  // namespace throng::secondary
