// readPng's size bound (core/image.h): checked from the header, before any pixel is decoded.
#include <doctest/doctest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"
#include "core/image.h"

using namespace throng;

namespace {

uint32_t crc32(const std::string& bytes) {
  uint32_t crc = 0xffffffffu;
  for (unsigned char c : bytes) {
    crc ^= c;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::string bigEndian(uint32_t v) {
  return {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
}

std::string chunk(const std::string& type, const std::string& data) {
  return bigEndian(uint32_t(data.size())) + type + data + bigEndian(crc32(type + data));
}

// A PNG whose header claims width x height (8-bit grey) and whose pixel data is one empty row:
// the header alone says how much decoding it would take.
std::filesystem::path writeClaimingPng(const std::string& name, uint32_t width, uint32_t height) {
  const std::string ihdr =
      bigEndian(width) + bigEndian(height) + std::string("\x08\x00\x00\x00\x00", 5);
  const std::string idat("\x78\x01\x01\x01\x00\xfe\xff\x00\x00\x01\x00\x01",
                         12);  // zlib: one 0 byte
  const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) +
                          chunk("IDAT", idat) + chunk("IEND", "");
  const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path, std::ios::binary) << png;
  return path;
}

}  // namespace

TEST_CASE("image: a PNG header claiming more than the size limit is refused before decoding") {
  const auto path = writeClaimingPng("throng_claims_12000.png", 12000, 12000);
  CHECK_THROWS_WITH_AS(readPng(path),
                       doctest::Contains("throng_claims_12000.png: image of 12000x12000 pixels"),
                       Error);
  CHECK_THROWS_WITH_AS(readPng(path), doctest::Contains("64 Mpixel"), Error);
  const auto wide = writeClaimingPng("throng_claims_wide.png", 20000, 2);
  CHECK_THROWS_WITH_AS(readPng(wide), doctest::Contains("at most 16384 pixels per side"), Error);
  std::filesystem::remove(path);
  std::filesystem::remove(wide);
}

TEST_CASE("image: sizes within the limit still load") {
  CHECK_NOTHROW(checkImageSize("a.png", 8192, 8192));
  CHECK_NOTHROW(checkImageSize("a.png", 16384, 4096));
  CHECK_THROWS_AS(checkImageSize("a.png", 8193, 8192), Error);
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "throng_small_ok.png";
  ImageRgba8 image(5, 3, Rgba8{10, 20, 30, 255});
  writePngAtomic(path, image);
  const ImageRgba8 back = readPng(path);
  CHECK(back.width == 5);
  CHECK(back.height == 3);
  CHECK(back.at(4, 2) == Rgba8{10, 20, 30, 255});
  std::filesystem::remove(path);
}

TEST_CASE("image: a chunk claiming more bytes than the file holds is refused before decoding") {
  // A 12 x 30 image whose IDAT claims 1.8 GB (a fuzzer's find): stb would grow its buffer first.
  const std::string ihdr = bigEndian(12) + bigEndian(30) + std::string("\x08\x00\x00\x00\x00", 5);
  const std::string png = std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) +
                          bigEndian(1802961038u) + "IDAT" + std::string(40, '\0');
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "throng_long_chunk.png";
  std::ofstream(path, std::ios::binary) << png;
  CHECK_THROWS_WITH_AS(readPng(path),
                       doctest::Contains("PNG chunk 'IDAT' at byte 33 claims 1802961038 bytes"),
                       Error);
  std::filesystem::remove(path);
}
