#pragma once
// Motion pairs for the synthesis tests: a synthetic random pair (always available) and the
// real-capture pairs from ../shared/data when present.
#include <optional>
#include <string>

#include "anim/motion_texture.h"
#include "anim/skeleton.h"

namespace throng::test {

// Random skeleton (parents-first tree), random unit rotations per frame, cyclic root track.
anim::MotionPair syntheticPair(int joints, int slowFrames, int fastFrames, uint32_t seed);

// The built-in run pair (anim::defaultRunPair), made once, and its skeleton.
const anim::MotionPair& builtInRunPair();
const anim::Skeleton& builtInRunSkeleton();

// Max |a - b| over two float arrays of equal length.
float maxAbsDifference(const float* a, const float* b, size_t count);

}  // namespace throng::test
