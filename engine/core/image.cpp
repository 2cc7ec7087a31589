#include "core/image.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>

#include "core/error.h"
#include "core/file_io.h"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace throng {

void checkImageSize(const std::filesystem::path& path, long long width, long long height) {
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide ||
      width * height > kMaxImagePixels)
    fail(path.string(), ": image of ", width, "x", height, " pixels; expected at most ",
         kMaxImageSide, " pixels per side and ", kMaxImagePixels, " pixels (",
         kMaxImagePixels / (1024 * 1024), " Mpixel, 8192x8192) in all");
}

namespace {
// Every chunk's length must fit in the file: stb grows its buffer to a claimed IDAT length
// before reading it, so a 200-byte file claiming 1.8 GB would allocate that much first.
void checkPngChunks(const std::filesystem::path& path, const std::string& bytes) {
  constexpr size_t kSignature = 8, kHeader = 8, kCrc = 4;  // chunk: length, type, data, CRC
  if (bytes.size() < kSignature || bytes.compare(0, kSignature, "\x89PNG\r\n\x1a\n") != 0) return;
  size_t pos = kSignature;
  // Every chunk whose length field is present is checked, the last one too: a chunk cut off
  // before its CRC still makes the decoder allocate what its length claims.
  while (pos + kHeader <= bytes.size()) {
    const auto byte = [&](size_t k) { return uint32_t(uint8_t(bytes[pos + k])); };
    const uint32_t length = byte(0) << 24 | byte(1) << 16 | byte(2) << 8 | byte(3);
    const std::string type = bytes.substr(pos + 4, 4);
    const size_t left = bytes.size() - pos - kHeader;
    if (size_t(length) + kCrc > left)
      fail(path.string(), ": PNG chunk '", type, "' at byte ", pos, " claims ", length,
           " bytes and its CRC but ", left, " remain (truncated or corrupt file)");
    if (type == "IEND") return;
    pos += kHeader + length + kCrc;
  }
}
}  // namespace

ImageRgba8 readPng(const std::filesystem::path& path) {
  std::string bytes = readTextFile(path);
  if (bytes.size() > size_t(std::numeric_limits<int>::max()))
    fail(path.string(), ": ", bytes.size(), " bytes; PNG files of up to 2 GiB are read");
  int w = 0, h = 0, channels = 0;
  // The header's size is checked before decoding: a small file can claim a huge image.
  if (stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                            static_cast<int>(bytes.size()), &w, &h, &channels)) {
    checkImageSize(path, w, h);
  }
  checkPngChunks(path, bytes);
  stbi_uc* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                        static_cast<int>(bytes.size()), &w, &h, &channels, 4);
  if (!data) fail(path.string(), ": not a readable PNG (", stbi_failure_reason(), ")");
  ImageRgba8 image(w, h);
  std::copy_n(reinterpret_cast<const Rgba8*>(data), size_t(w) * h, image.pixels.data());
  stbi_image_free(data);
  return image;
}

ImageDiff compareImages(const ImageRgba8& actual, const ImageRgba8& expected, int pixelThreshold) {
  if (actual.width != expected.width || actual.height != expected.height) {
    fail("image size mismatch: actual ", actual.width, "x", actual.height, ", expected ",
         expected.width, "x", expected.height);
  }
  ImageDiff diff;
  diff.diffImage = ImageRgba8(actual.width, actual.height);
  double sum = 0;
  size_t different = 0;
  for (size_t i = 0; i < actual.pixels.size(); ++i) {
    const Rgba8& a = actual.pixels[i];
    const Rgba8& e = expected.pixels[i];
    int dr = std::abs(a.r - e.r), dg = std::abs(a.g - e.g), db = std::abs(a.b - e.b);
    int m = std::max({dr, dg, db});
    sum += dr + dg + db;
    diff.maxError = std::max(diff.maxError, m);
    if (m > pixelThreshold) ++different;
    uint8_t v = static_cast<uint8_t>(std::min(255, m * 4));
    diff.diffImage.pixels[i] = {v, static_cast<uint8_t>(m > pixelThreshold ? 0 : v), 0, 255};
  }
  diff.meanAbsError = sum / (3.0 * std::max<size_t>(1, actual.pixels.size()));
  diff.fractionDifferent = double(different) / std::max<size_t>(1, actual.pixels.size());
  return diff;
}

}  // namespace throng
