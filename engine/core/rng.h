#pragma once
// PCG32: small, fast, and identical on every platform, so scenarios are deterministic by seed.
#include <cstdint>

namespace throng {
class Rng {
 public:
  explicit Rng(uint64_t seed, uint64_t stream = 54u) {
    inc_ = (stream << 1u) | 1u;
    next();
    state_ += seed;
    next();
  }
  uint32_t next() {
    uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + inc_;
    uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31));
  }
  // Uniform in [0, 1).
  float uniform() { return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f); }
  float uniform(float lo, float hi) { return lo + (hi - lo) * uniform(); }

 private:
  uint64_t state_ = 0;
  uint64_t inc_ = 0;
};
}  // namespace throng
