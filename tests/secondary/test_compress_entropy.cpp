// The .tsc's entropy coder: exact round trips (small, large and extreme integers, block resets),
// sizes close to the source's entropy, and clear errors on a stream cut short.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>

#include "core/error.h"
#include "secondary/cloth_entropy.h"

using namespace throng;
using namespace throng::secondary;

namespace {
// Bits per value of a Gaussian of deviation sigma rounded to integers (sigma ≫ 1/2):
// ½ log2(2πe σ²). (The histogram of a sample underestimates it when values rarely repeat.)
double gaussianBits(double sigma) {
  return 0.5 * std::log2(2.0 * M_PI * M_E * sigma * sigma);
}
}  // namespace

TEST_CASE("entropy coder: exact round trip of small, large and extreme integers") {
  std::vector<int32_t> values{0,
                              1,
                              -1,
                              2,
                              -2,
                              255,
                              -256,
                              32767,
                              -32767,
                              65535,
                              1 << 20,
                              -(1 << 30),
                              std::numeric_limits<int32_t>::max(),
                              std::numeric_limits<int32_t>::min() + 1,
                              0,
                              0,
                              7};
  std::mt19937 rng(3);
  std::uniform_int_distribution<int32_t> any(-100000, 100000);
  for (int i = 0; i < 5000; ++i) values.push_back(any(rng));
  for (size_t block : {size_t(1), size_t(7), size_t(1000), values.size()}) {
    std::vector<uint8_t> bytes = encodeIntegerBlocks(values, block);
    CHECK(decodeIntegerBlocks(bytes, values.size(), block, "memory") == values);
  }
  CHECK(decodeIntegerBlocks(encodeIntegerBlocks({}, 4), 0, 4, "memory").empty());
}

TEST_CASE("entropy coder: near the entropy of a skewed source, one model per block") {
  // Two blocks of very different spread (like a large and a small basis' coefficients).
  std::mt19937 rng(11);
  std::normal_distribution<double> wide(0.0, 3000.0), narrow(0.0, 2.0);
  std::vector<int32_t> values;
  for (int i = 0; i < 20000; ++i) values.push_back(int32_t(std::lround(wide(rng))));
  for (int i = 0; i < 20000; ++i) values.push_back(int32_t(std::lround(narrow(rng))));
  const double entropy = 20000.0 * (gaussianBits(3000.0) + gaussianBits(2.0)) / 8.0;
  std::vector<uint8_t> bytes = encodeIntegerBlocks(values, 20000);
  CHECK(double(bytes.size()) < 1.04 * entropy);  // within 4% of the source's entropy
  CHECK(double(bytes.size()) > 0.97 * entropy);
  // One model for both blocks costs more: the narrow block pays for the wide one's spread.
  CHECK(encodeIntegerBlocks(values, values.size()).size() > bytes.size());
  CHECK(bytes.size() < values.size() * 6 / 5);  // under 10 bits a value, not 16
  CHECK(decodeIntegerBlocks(bytes, values.size(), 20000, "memory") == values);
}

TEST_CASE("entropy coder: a stream cut short gives an error naming the source") {
  std::vector<int32_t> values(4000);
  std::mt19937 rng(5);
  std::uniform_int_distribution<int32_t> any(-5000, 5000);
  for (int32_t& v : values) v = any(rng);
  std::vector<uint8_t> bytes = encodeIntegerBlocks(values, 1000);
  std::vector<uint8_t> cut(bytes.begin(), bytes.begin() + long(bytes.size() / 2));
  CHECK_THROWS_WITH_AS(decodeIntegerBlocks(cut, values.size(), 1000, "cape.tsc"),
                       doctest::Contains("cape.tsc: the entropy-coded stream ends"), Error);
}

TEST_CASE("entropy coder: a garbage stream decoding to 32-bit lengths stays inside the model") {
  // Eight 0xff bytes decode to the longest lengths: the mantissa bits of length 32 must land in
  // the model's own table, not in whatever follows it in memory.
  struct Guarded {
    IntegerModel model;
    uint16_t canary[64];
  } guarded;
  std::fill(std::begin(guarded.canary), std::end(guarded.canary), uint16_t(0x5a5a));
  const std::vector<uint8_t> garbage(8, 0xff);
  RangeDecoder decoder(garbage);
  int64_t largest = 0;
  for (int i = 0; i < 64; ++i)
    largest = std::max(largest, int64_t(std::llabs(decoder.decodeInteger(guarded.model))));
  CHECK(largest >= std::numeric_limits<int32_t>::max());  // saturated, not wrapped
  for (uint16_t c : guarded.canary) REQUIRE(c == 0x5a5a);
  // The encoder's side of the same length: −2^31 round trips.
  const std::vector<int32_t> extreme{std::numeric_limits<int32_t>::min(), 3,
                                     std::numeric_limits<int32_t>::min()};
  CHECK(decodeIntegerBlocks(encodeIntegerBlocks(extreme, 3), 3, 3, "memory") == extreme);
  CHECK_THROWS_WITH_AS(decodeIntegerBlocks(garbage, 1000, 1000, "g.tsc"),
                       doctest::Contains("g.tsc: the entropy-coded stream ends"), Error);
}

TEST_CASE("entropy coder: a claimed count beyond what the bytes can hold is refused up front") {
  // The densest stream there is (all zeros) stays within maxDecodableValues.
  const std::vector<int32_t> zeros(2000000, 0);
  const std::vector<uint8_t> bytes = encodeIntegerBlocks(zeros, zeros.size());
  CHECK(zeros.size() <= maxDecodableValues(bytes.size()));
  CHECK(zeros.size() > maxDecodableValues(bytes.size()) / 2);  // and the bound is not loose
  CHECK(decodeIntegerBlocks(bytes, zeros.size(), zeros.size(), "memory") == zeros);
  // 300 million values from 16 bytes: an error before any allocation, not a 1.2 GB vector.
  const std::vector<uint8_t> small(16, 0);
  CHECK_THROWS_WITH_AS(decodeIntegerBlocks(small, 300000000, 1000, "g.tsc"),
                       doctest::Contains("g.tsc: 300000000 values claimed"), Error);
  CHECK_THROWS_WITH_AS(
      decodeIntegerBlocks(small, std::numeric_limits<size_t>::max(), 1000, "g.tsc"),
      doctest::Contains("values claimed"), Error);
}
