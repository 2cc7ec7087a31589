#pragma once
// Entropy coding of the .tsc's quantized integers (bases and coefficients). Most of a compressed
// cape's bytes are coefficients whose values cluster near zero with a spread that differs by
// basis, so an adaptive binary range coder (the LZMA kind: 11-bit probabilities, 32-bit range)
// with one model per basis gets close to each basis' own entropy; a general-purpose byte
// compressor sees 16-bit words it cannot model and does worse. Written here (no dependency):
// about a hundred lines, deterministic, and tested by round trips.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace throng::secondary {

// Adaptive model of signed integers: a zero flag, a sign, the bit length of |x| in unary, then
// the bits below the leading one, each an adaptive bit indexed by (length, position). Lengths run
// 1 … kMaxLength inclusive (|INT32_MIN| = 2^31 has 32 bits, and so can any garbage stream), so
// the mantissa table has a row for every length up to kMaxLength itself.
struct IntegerModel {
  static constexpr uint32_t kMaxLength = 32;
  uint16_t zero = 1024, sign = 1024;
  uint16_t length[kMaxLength] = {};
  uint16_t mantissa[kMaxLength + 1][kMaxLength] = {};
  IntegerModel();
};

// The most values a stream of `bytes` bytes can decode to: every value costs at least its zero
// flag, and an adaptive probability never passes 2017/2048, so a coded bit carries at least
// log2(2048/2017) > 1/46 bit; a byte (plus the decoder's slack) holds at most 8 × 46 values.
// Readers check a claimed count against it before they allocate.
uint64_t maxDecodableValues(uint64_t bytes);

class RangeEncoder {
 public:
  void encodeBit(uint16_t& probability, uint32_t bit);
  void encodeInteger(IntegerModel& model, int32_t value);
  // Flushes and returns the bytes; the encoder is spent afterwards.
  std::vector<uint8_t> finish();

 private:
  void shiftLow();
  uint64_t low_ = 0;
  uint32_t range_ = 0xFFFFFFFFu;
  uint8_t cache_ = 0;
  uint64_t cacheSize_ = 1;
  std::vector<uint8_t> bytes_;
};

// Reads past the end as zeros (the file's checksum has already vouched for the bytes; a stream
// that still decodes to garbage is caught by the caller's range checks, never by a crash).
class RangeDecoder {
 public:
  explicit RangeDecoder(std::span<const uint8_t> bytes);
  uint32_t decodeBit(uint16_t& probability);
  int32_t decodeInteger(IntegerModel& model);
  // Bytes consumed beyond the end of the input (0 for a well-formed stream).
  size_t overrun() const { return overrun_; }

 private:
  uint8_t next();
  std::span<const uint8_t> bytes_;
  size_t at_ = 0, overrun_ = 0;
  uint32_t range_ = 0xFFFFFFFFu, code_ = 0;
};

// Blocks of integers, block k coded with its own model (e.g. one per basis).
std::vector<uint8_t> encodeIntegerBlocks(std::span<const int32_t> values, size_t blockSize);
// Throws Error naming `sourceName` when the stream runs past its end, or when `count` exceeds
// maxDecodableValues(bytes.size()) (checked before anything is allocated).
std::vector<int32_t> decodeIntegerBlocks(std::span<const uint8_t> bytes, size_t count,
                                         size_t blockSize, const std::string& sourceName);

}  // namespace throng::secondary
