#pragma once
// How similar two cloth states at the same primary node are (the merge error of Kim et al.
// 2013): the L∞ norm over vertices of the position difference and of the velocity difference
// times a time scale (so both are in metres), plus a garment-specific term.
#include <cstdint>
#include <functional>

#include "secondary/offline/secondary_graph.h"

namespace throng::secondary {

// Extra error (metres, ≥ 0) between two states at `node`, e.g. a cape over vs behind the
// shoulder. Must be deterministic and thread-safe.
using GarmentTerm = std::function<float(FrameView a, FrameView b, uint32_t node)>;

struct MergeMetric {
  float velocityScale = 0.1f;  // seconds: velocity differences count as this many seconds of drift
  GarmentTerm garment;         // optional
};

// max over vertices of max(|Δx|, velocityScale·|Δv|): returns early (any value > bound) once
// the distance exceeds `bound`.
float linfDistance(FrameView a, FrameView b, float velocityScale, float bound = INFINITY);
float mergeError(const MergeMetric& metric, FrameView a, FrameView b, uint32_t node);

struct MergeTarget {
  uint32_t state = kNoState;
  float error = INFINITY;
};
// The state at primary `node` most similar to `cloth` (lowest index among equals).
MergeTarget findMergeTarget(const SecondaryGraph& g, const MergeMetric& metric, uint32_t node,
                            FrameView cloth);

}  // namespace throng::secondary
