#pragma once
// 8-bit RGBA images in memory, PNG read (stb) and write (ISA-L's igzip), and the comparison used
// by golden tests.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace throng {

struct Rgba8 {
  uint8_t r = 0, g = 0, b = 0, a = 255;
  friend bool operator==(const Rgba8&, const Rgba8&) = default;
};

struct ImageRgba8 {
  int width = 0;
  int height = 0;
  std::vector<Rgba8> pixels;  // row-major, top row first

  ImageRgba8() = default;
  ImageRgba8(int w, int h, Rgba8 fill = {}) : width(w), height(h), pixels(size_t(w) * h, fill) {}
  Rgba8& at(int x, int y) { return pixels[size_t(y) * width + x]; }
  const Rgba8& at(int x, int y) const { return pixels[size_t(y) * width + x]; }
};

// The largest image readPng decodes: 16384 pixels per side and 64 Mpixel (8192 x 8192) in
// all, 256 MiB as RGBA. The size in the header is checked before anything is decoded, so a
// small file claiming a huge image (an all-black 12000 x 12000 PNG is 420 KB) is refused
// instead of allocating gigabytes.
inline constexpr long long kMaxImageSide = 16384;
inline constexpr long long kMaxImagePixels = 64ll * 1024 * 1024;
// Throws Error naming the file when width x height exceeds the limits above.
void checkImageSize(const std::filesystem::path& path, long long width, long long height);

// Throws Error naming the file when it is missing, not a PNG or larger than the limits above.
ImageRgba8 readPng(const std::filesystem::path& path);
// A PNG file's bytes: 8-bit RGB when every pixel is opaque, RGBA otherwise. Fast rather than
// small (igzip level 1, one row filter).
std::vector<uint8_t> encodePng(const ImageRgba8& image);
// Written to a temporary name and renamed when complete.
void writePngAtomic(const std::filesystem::path& path, const ImageRgba8& image);

struct ImageDiff {
  double meanAbsError = 0;       // over RGB channels, 0..255
  double fractionDifferent = 0;  // pixels whose max channel error exceeds the threshold
  int maxError = 0;
  ImageRgba8 diffImage;  // per-pixel error amplified for people to look at
};
ImageDiff compareImages(const ImageRgba8& actual, const ImageRgba8& expected, int pixelThreshold);

}  // namespace throng
