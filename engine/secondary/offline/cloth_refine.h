#pragma once
// Coefficients chosen for the largest vertex error. The SVD's projection and the rounding of each
// coefficient to its step minimize squared error; the goal of the compressor is the largest error
// (L∞ over vertices). For a state whose decoded frame misses `target`, this walks its quantized
// coefficients one step at a time (greedy coordinate descent): at the worst vertex, try the bases
// that move it most towards the truth, keep the first step that lowers the state's largest error
// (or keeps it and lowers the total excess over the target), and stop when none does, the target
// is met or `maxSteps` is spent. The decoder is unchanged.
#include <cstdint>

#include "secondary/cloth_database.h"
#include "secondary/offline/cloth_compress.h"

namespace throng::secondary {

struct RefineReport {
  uint32_t statesAboveTarget = 0;  // before refining
  uint32_t statesRefined = 0;      // changed by at least one step
  uint64_t steps = 0;              // coefficient steps taken, all states
  ReconstructionError after;       // every state, after refining (as reconstructionError)
};

RefineReport refineCoefficients(const ClothFrames& frames, ClothDatabase& db, float target,
                                uint32_t maxSteps, unsigned threads);

}  // namespace throng::secondary
