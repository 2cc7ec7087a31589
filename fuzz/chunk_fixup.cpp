#include "chunk_fixup.h"

#include <cstring>

#include "core/binary_io.h"

namespace throng::fuzz {
namespace {
constexpr size_t kTotalBytesOffset =
    16;  // header: magic[8] | version u32 | chunkCount u32 | totalBytes u64

template <typename T>
void putLittleEndian(uint8_t* at, T value) {
  for (size_t i = 0; i < sizeof(T); ++i) at[i] = uint8_t(uint64_t(value) >> (8 * i));
}
}  // namespace

std::vector<uint8_t> withValidChunkTrailer(std::span<const uint8_t> input) {
  std::vector<uint8_t> bytes(input.begin(), input.end());
  if (bytes.size() < throng::kFileHeaderBytes + throng::kTrailerBytes) return bytes;
  putLittleEndian<uint64_t>(bytes.data() + kTotalBytesOffset, bytes.size());
  const size_t body = bytes.size() - throng::kTrailerBytes;
  putLittleEndian<uint32_t>(bytes.data() + body, throng::crc32Ieee({bytes.data(), body}));
  std::memcpy(bytes.data() + body + 4, "TEND", 4);
  return bytes;
}

}  // namespace throng::fuzz
