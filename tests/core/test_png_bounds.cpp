// PNG input bounds: a chunk cut off before its CRC is refused before the decoder allocates what
// its length claims (a fuzzer's 43-byte file asked stb for 1.1 GB).
#include <doctest/doctest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/image.h"

using namespace throng;
namespace fs = std::filesystem;

namespace {
std::string be32(uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}
fs::path writeBytes(const std::string& name, const std::string& bytes) {
  fs::path path = fs::temp_directory_path() / (name + std::to_string(::getpid()) + ".png");
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}
}  // namespace

TEST_CASE("png: a last chunk whose data and CRC are cut off is an error, not a huge allocation") {
  std::string png = "\x89PNG\r\n\x1a\n";
  png += be32(13) + "IHDR" + be32(4) + be32(4) + std::string("\x08\x06\x00\x00\x00", 5) + be32(0);
  png += be32(0x40000000u) + "IDAT";  // length and type, then the file ends
  fs::path path = writeBytes("throng_cut_chunk", png);
  CHECK_THROWS_WITH_AS(readPng(path), doctest::Contains("claims 1073741824 bytes"), Error);
  png += "abc";  // a few bytes more, still far from the claim
  path = writeBytes("throng_cut_chunk2", png);
  CHECK_THROWS_WITH_AS(readPng(path), doctest::Contains("truncated or corrupt"), Error);
  fs::remove(path);
}
