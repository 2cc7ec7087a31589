#include "secondary/cloth_decoder.h"

#include "core/error.h"

namespace throng::secondary {

DecodedBases dequantize(const ClothDatabase& db) {
  DecodedBases d;
  d.vertexCount = db.vertexCount;
  d.basisCount = db.basisCount();
  d.stateCount = db.stateCount();
  d.mean = db.mean;
  const size_t rows = size_t(db.vertexCount) * 3;
  d.bases.resize(rows * d.basisCount);
  for (uint32_t i = 0; i < d.basisCount; ++i)
    for (size_t r = 0; r < rows; ++r) d.bases[i * rows + r] = db.bases[i].value(r);
  d.coefficients.resize(db.coefficients.size());
  for (size_t k = 0; k < db.coefficients.size(); ++k)
    d.coefficients[k] = dequantizeCoefficient(db.coefficients[k]);
  return d;
}

void decodeStateSubset(const DecodedBases& d, uint32_t state, std::span<const uint32_t> order,
                       uint32_t basisCount, std::span<glm::vec3> out) {
  THRONG_CHECK(state < d.stateCount, "state ", state, " of ", d.stateCount);
  THRONG_CHECK(basisCount <= d.basisCount, "bases ", basisCount, " of ", d.basisCount);
  THRONG_CHECK(out.size() <= order.size(), "decode output larger than the vertex order");
  const size_t rows = size_t(d.vertexCount) * 3;
  const float* c = d.coefficients.data() + size_t(state) * d.basisCount;
  for (size_t k = 0; k < out.size(); ++k) {
    const size_t r = size_t(order[k]) * 3;
    glm::vec3 p(d.mean[r], d.mean[r + 1], d.mean[r + 2]);
    for (uint32_t i = 0; i < basisCount; ++i) {
      const float* b = d.bases.data() + i * rows + r;
      p += glm::vec3(b[0], b[1], b[2]) * c[i];
    }
    out[k] = p;
  }
}

void decodeState(const DecodedBases& d, uint32_t state, std::span<glm::vec3> out) {
  THRONG_CHECK(out.size() == d.vertexCount, "decode output holds ", out.size(),
               " vertices, expected ", d.vertexCount);
  thread_local std::vector<uint32_t> identity;
  if (identity.size() < d.vertexCount) {
    identity.resize(d.vertexCount);
    for (uint32_t v = 0; v < d.vertexCount; ++v) identity[v] = v;
  }
  decodeStateSubset(d, state, identity, d.basisCount, out);
}

}  // namespace throng::secondary
