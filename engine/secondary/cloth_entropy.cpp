#include "secondary/cloth_entropy.h"

#include <algorithm>

#include "core/error.h"

namespace throng::secondary {

namespace {
constexpr uint32_t kProbabilityBits = 11;
constexpr uint32_t kOne = 1u << kProbabilityBits;  // probabilities of a 0 bit, in 1/2048
constexpr uint32_t kAdaptShift = 5;                // adaptation rate: 1/32 per coded bit
constexpr uint32_t kTop = 1u << 24;                // renormalise when the range drops below it

uint32_t bitLength(uint32_t v) {
  uint32_t n = 0;
  while (v) {
    ++n;
    v >>= 1;
  }
  return n;
}
}  // namespace

IntegerModel::IntegerModel() {
  std::fill(std::begin(length), std::end(length), uint16_t(kOne / 2));
  for (auto& row : mantissa) std::fill(std::begin(row), std::end(row), uint16_t(kOne / 2));
}

void RangeEncoder::encodeBit(uint16_t& p, uint32_t bit) {
  const uint32_t bound = (range_ >> kProbabilityBits) * p;
  if (bit == 0) {
    range_ = bound;
    p = uint16_t(p + ((kOne - p) >> kAdaptShift));
  } else {
    low_ += bound;
    range_ -= bound;
    p = uint16_t(p - (p >> kAdaptShift));
  }
  while (range_ < kTop) {
    range_ <<= 8;
    shiftLow();
  }
}

// Carry propagation as in LZMA: a byte is held back (cache) while a carry may still reach it.
void RangeEncoder::shiftLow() {
  if (uint32_t(low_) < 0xFF000000u || (low_ >> 32) != 0) {
    const uint8_t carry = uint8_t(low_ >> 32);
    uint8_t held = cache_;
    do {
      bytes_.push_back(uint8_t(held + carry));
      held = 0xFF;
    } while (--cacheSize_ != 0);
    cache_ = uint8_t(low_ >> 24);
  }
  ++cacheSize_;
  low_ = (low_ & 0x00FFFFFFu) << 8;
}

std::vector<uint8_t> RangeEncoder::finish() {
  for (int i = 0; i < 5; ++i) shiftLow();
  // The first byte is always the initial (zero) cache: the decoder skips it.
  return std::vector<uint8_t>(bytes_.begin() + 1, bytes_.end());
}

// Zero flag; sign; length n = bit length of |x| in unary over length[1 … n) (|x| ≥ 1 so n ≥ 1);
// then bits n−2 … 0 of |x|, each with its own adaptive probability.
void RangeEncoder::encodeInteger(IntegerModel& m, int32_t value) {
  encodeBit(m.zero, value == 0 ? 0u : 1u);
  if (value == 0) return;
  encodeBit(m.sign, value < 0 ? 1u : 0u);
  const uint32_t magnitude = value < 0 ? uint32_t(-int64_t(value)) : uint32_t(value);
  const uint32_t n = bitLength(magnitude);
  for (uint32_t k = 1; k < n; ++k) encodeBit(m.length[k], 1u);
  if (n < IntegerModel::kMaxLength) encodeBit(m.length[n], 0u);
  for (uint32_t k = n - 1; k-- > 0;) encodeBit(m.mantissa[n][k], (magnitude >> k) & 1u);
}

RangeDecoder::RangeDecoder(std::span<const uint8_t> bytes) : bytes_(bytes) {
  for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next();
}

uint8_t RangeDecoder::next() {
  if (at_ < bytes_.size()) return bytes_[at_++];
  ++overrun_;
  return 0;
}

uint32_t RangeDecoder::decodeBit(uint16_t& p) {
  const uint32_t bound = (range_ >> kProbabilityBits) * p;
  uint32_t bit;
  if (code_ < bound) {
    range_ = bound;
    p = uint16_t(p + ((kOne - p) >> kAdaptShift));
    bit = 0;
  } else {
    code_ -= bound;
    range_ -= bound;
    p = uint16_t(p - (p >> kAdaptShift));
    bit = 1;
  }
  while (range_ < kTop) {
    range_ <<= 8;
    code_ = (code_ << 8) | next();
  }
  return bit;
}

int32_t RangeDecoder::decodeInteger(IntegerModel& m) {
  if (decodeBit(m.zero) == 0) return 0;
  const bool negative = decodeBit(m.sign) != 0;
  uint32_t n = 1;
  while (n < IntegerModel::kMaxLength && decodeBit(m.length[n])) ++n;
  uint32_t magnitude = 1;
  for (uint32_t k = n - 1; k-- > 0;) magnitude = (magnitude << 1) | decodeBit(m.mantissa[n][k]);
  // Length 32 holds magnitudes up to 2^32 − 1; only −2^31 is valid among them: saturate the rest.
  const int64_t v = negative ? -int64_t(magnitude) : int64_t(magnitude);
  return int32_t(std::clamp<int64_t>(v, INT32_MIN, INT32_MAX));
}

std::vector<uint8_t> encodeIntegerBlocks(std::span<const int32_t> values, size_t blockSize) {
  THRONG_CHECK(blockSize > 0 || values.empty(), "integer blocks of size 0");
  RangeEncoder encoder;
  IntegerModel model;
  for (size_t i = 0; i < values.size(); ++i) {
    if (i % blockSize == 0) model = IntegerModel();
    encoder.encodeInteger(model, values[i]);
  }
  return encoder.finish();
}

uint64_t maxDecodableValues(uint64_t bytes) {
  // The decoder reads 4 bytes ahead and tolerates 4 past the end (decodeIntegerBlocks).
  constexpr uint64_t kValuesPerByte = 8 * 46, kSlackBytes = 8;
  return (bytes + kSlackBytes) * kValuesPerByte;
}

std::vector<int32_t> decodeIntegerBlocks(std::span<const uint8_t> bytes, size_t count,
                                         size_t blockSize, const std::string& name) {
  THRONG_CHECK(blockSize > 0 || count == 0, "integer blocks of size 0");
  if (count > maxDecodableValues(bytes.size()))
    fail(name, ": ", count, " values claimed from an entropy-coded stream of ", bytes.size(),
         " bytes (at most ", maxDecodableValues(bytes.size()), " fit)");
  RangeDecoder decoder(bytes);
  IntegerModel model;
  std::vector<int32_t> values(count);
  for (size_t i = 0; i < count; ++i) {
    if (i % blockSize == 0) model = IntegerModel();
    values[i] = decoder.decodeInteger(model);
    // A valid stream ends within the encoder's 4 flush bytes of slack; far beyond is garbage.
    if (decoder.overrun() > 4)
      fail(name, ": the entropy-coded stream ends after ", i, " of ", count, " values");
  }
  return values;
}

}  // namespace throng::secondary
