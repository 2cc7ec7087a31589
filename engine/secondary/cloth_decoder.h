#pragma once
// The CPU decoder of a compressed cloth database: state s → V positions = mean + Σ_i B'_i c'_si,
// with B' and c' dequantized once to floats. It is the twin of shaders/cloth_decode.comp (same
// layout, same summation order), and what the compressor measures its error with.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "secondary/cloth_database.h"

namespace throng::secondary {

struct DecodedBases {
  uint32_t vertexCount = 0;
  uint32_t basisCount = 0;
  uint32_t stateCount = 0;
  std::vector<float> mean;          // 3V, row 3v + axis
  std::vector<float> bases;         // basis-major: bases[i · 3V + row] = offset_i + q · step_i
  std::vector<float> coefficients;  // state-major: coefficients[s · b + i] = q / 32767
};
DecodedBases dequantize(const ClothDatabase& db);

// Positions of `state` for every vertex, with every basis.
void decodeState(const DecodedBases& d, uint32_t state, std::span<glm::vec3> out);
// Positions of vertices order[0 … out.size()) with the first `basisCount` bases (the LOD decode:
// out[k] is vertex order[k]).
void decodeStateSubset(const DecodedBases& d, uint32_t state, std::span<const uint32_t> order,
                       uint32_t basisCount, std::span<glm::vec3> out);

}  // namespace throng::secondary
