#pragma once
// Rewrites one chunk of a binary_io file (a .tsc, a .tsg) and recomputes its size and checksum, so
// a test can hand a reader a well-formed file whose content lies: a count no other chunk backs, a
// garbage entropy stream. (The layout is the one binary_io.h documents.)
#include <cstring>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "core/binary_io.h"

namespace throng::test {

struct RawChunk {
  std::string tag;
  uint32_t type = 0, elementBytes = 0;
  uint64_t count = 0;
  std::vector<uint8_t> payload;
};

inline std::vector<RawChunk> rawChunks(const std::vector<uint8_t>& file) {
  uint32_t chunkCount;
  std::memcpy(&chunkCount, file.data() + 12, 4);
  std::vector<RawChunk> chunks;
  size_t at = throng::kFileHeaderBytes;
  for (uint32_t i = 0; i < chunkCount; ++i) {
    RawChunk c;
    c.tag.assign(reinterpret_cast<const char*>(file.data() + at), 4);
    std::memcpy(&c.type, file.data() + at + 4, 4);
    std::memcpy(&c.elementBytes, file.data() + at + 8, 4);
    std::memcpy(&c.count, file.data() + at + 16, 8);
    at += throng::kChunkHeaderBytes;
    const size_t bytes = size_t(c.count * c.elementBytes);
    c.payload.assign(file.begin() + long(at), file.begin() + long(at + bytes));
    at += (bytes + 7) & ~size_t(7);
    chunks.push_back(std::move(c));
  }
  return chunks;
}

// The file with `edit` applied to chunk `tag` (which must exist); `count` follows the payload
// unless the edit sets it (a count that lies about the payload is then the caller's choice).
template <typename Edit>
std::vector<uint8_t> patchChunk(const std::vector<uint8_t>& file, const std::string& tag,
                                Edit&& edit) {
  std::vector<RawChunk> chunks = rawChunks(file);
  bool found = false;
  for (RawChunk& c : chunks)
    if (c.tag == tag) {
      edit(c);
      found = true;
    }
  REQUIRE(found);
  std::vector<uint8_t> out(file.begin(), file.begin() + throng::kFileHeaderBytes);
  for (const RawChunk& c : chunks) {
    uint8_t h[throng::kChunkHeaderBytes] = {};
    std::memcpy(h, c.tag.data(), 4);
    std::memcpy(h + 4, &c.type, 4);
    std::memcpy(h + 8, &c.elementBytes, 4);
    std::memcpy(h + 16, &c.count, 8);
    out.insert(out.end(), h, h + sizeof h);
    out.insert(out.end(), c.payload.begin(), c.payload.end());
    out.resize((out.size() + 7) & ~size_t(7), 0);
  }
  const uint64_t total = out.size() + throng::kTrailerBytes;
  std::memcpy(out.data() + 16, &total, 8);
  const uint32_t crc = throng::crc32Ieee(out);
  const uint8_t* c = reinterpret_cast<const uint8_t*>(&crc);
  out.insert(out.end(), c, c + 4);
  out.insert(out.end(), {'T', 'E', 'N', 'D'});
  return out;
}

// Replaces the payload (and count) of chunk `tag` with `payload`, elements of the same size.
inline std::vector<uint8_t> replacePayload(const std::vector<uint8_t>& file, const std::string& tag,
                                           const std::vector<uint8_t>& payload) {
  return patchChunk(file, tag, [&](RawChunk& c) {
    REQUIRE(payload.size() % c.elementBytes == 0);
    c.payload = payload;
    c.count = payload.size() / c.elementBytes;
  });
}

template <typename T>
std::vector<uint8_t> bytesOfValue(const T& value) {
  const uint8_t* p = reinterpret_cast<const uint8_t*>(&value);
  return {p, p + sizeof(T)};
}

}  // namespace throng::test
