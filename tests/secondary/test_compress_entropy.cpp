// The .tsc's entropy coder: exact round trips (small, large and extreme integers, block resets),
// sizes close to the source's entropy, and clear errors on a stream cut short.
#include <doctest/doctest.h>

#include <cmath>
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
  std::vector<int32_t> values{0,     1,      -1,    2,         -2,       255,      -256, 32767,
                              -32767, 65535, 1 << 20, -(1 << 30), std::numeric_limits<int32_t>::max(),
                              std::numeric_limits<int32_t>::min() + 1, 0, 0, 7};
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
