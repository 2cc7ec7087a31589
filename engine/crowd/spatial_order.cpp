#include "crowd/spatial_order.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/error.h"

namespace throng::crowd {

namespace {

// The bits of v spread to the even positions.
uint64_t spreadBits(uint32_t v) {
  uint64_t x = v & 0xffffu;
  x = (x | (x << 8)) & 0x00ff00ffu;
  x = (x | (x << 4)) & 0x0f0f0f0fu;
  x = (x | (x << 2)) & 0x33333333u;
  x = (x | (x << 1)) & 0x55555555u;
  return x;
}

uint32_t gridCell(float v, float lo, float span) {
  const float t = span > 0.0f ? (v - lo) / span : 0.0f;
  return uint32_t(std::clamp(t, 0.0f, 1.0f) * 65535.0f);
}

}  // namespace

std::vector<uint32_t> spatialOrder(const Crowd& crowd) {
  glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
  for (const glm::vec4& p : crowd.placement) {
    lo = glm::min(lo, glm::vec2(p.x, p.z));
    hi = glm::max(hi, glm::vec2(p.x, p.z));
  }
  std::vector<uint64_t> codes(crowd.size());
  for (size_t i = 0; i < crowd.size(); ++i) {
    const glm::vec4& p = crowd.placement[i];
    codes[i] = spreadBits(gridCell(p.x, lo.x, hi.x - lo.x)) |
               (spreadBits(gridCell(p.z, lo.y, hi.y - lo.y)) << 1);
  }
  std::vector<uint32_t> order(crowd.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](uint32_t a, uint32_t b) { return codes[a] < codes[b]; });
  return order;
}

Crowd permuted(const Crowd& crowd, std::span<const uint32_t> order) {
  THRONG_CHECK(order.size() == crowd.size(), "an order of ", order.size(), " for ", crowd.size(),
               " characters");
  Crowd out;
  out.steering = crowd.steering;
  out.resize(crowd.size());
  for (size_t k = 0; k < order.size(); ++k) {
    THRONG_CHECK(order[k] < crowd.size(), "order names character ", order[k], " of ", crowd.size());
    out.placement[k] = crowd.placement[order[k]];
    out.motion[k] = crowd.motion[order[k]];
    if (!crowd.clipSet.empty()) out.clipSet[k] = crowd.clipSet[order[k]];
  }
  return out;
}

std::vector<uint32_t> permuted(std::span<const uint32_t> values, std::span<const uint32_t> order) {
  if (values.empty()) return {};
  THRONG_CHECK(values.size() == order.size(), order.size(), " places for ", values.size(),
               " values");
  std::vector<uint32_t> out(order.size());
  for (size_t k = 0; k < order.size(); ++k) {
    THRONG_CHECK(order[k] < values.size(), "order names value ", order[k], " of ", values.size());
    out[k] = values[order[k]];
  }
  return out;
}

}  // namespace throng::crowd
