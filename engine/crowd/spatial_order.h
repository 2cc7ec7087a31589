#pragma once
// Characters numbered in space: the order of a crowd whose consecutive characters stand near
// each other (a Morton curve over their starting places), for passes that work on runs of
// consecutive characters as one unit (the update-rate LOD's chunks, synth/update_rate.h).
#include <cstdint>
#include <span>
#include <vector>

#include "crowd/crowd.h"

namespace throng::crowd {

// The character indices in Morton order of their (x, z) places on a 65536² grid over the
// crowd's bounds; ties keep their order.
std::vector<uint32_t> spatialOrder(const Crowd& crowd);
// Character k of the result is character order[k] of `crowd` (order: a permutation).
Crowd permuted(const Crowd& crowd, std::span<const uint32_t> order);
// A per-character array in the same order.
std::vector<uint32_t> permuted(std::span<const uint32_t> values, std::span<const uint32_t> order);

}  // namespace throng::crowd
