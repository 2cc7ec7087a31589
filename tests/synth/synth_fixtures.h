#pragma once
// Motion pairs for the synthesis tests: a synthetic random pair (always available) and the
// real-capture pairs from ../shared/data when present.
#include <optional>
#include <string>

#include "anim/motion_texture.h"

namespace throng::test {

// Random skeleton (parents-first tree), random unit rotations per frame, cyclic root track.
anim::MotionPair syntheticPair(int joints, int slowFrames, int fastFrames, uint32_t seed);

// Max |a - b| over two float arrays of equal length.
float maxAbsDifference(const float* a, const float* b, size_t count);

}  // namespace throng::test
