#pragma once
// Storyboards drawn in code for the tests (no binary fixtures): glyphs through the encoder,
// and single pixels for the broken cases the encoder refuses to make.
#include <filesystem>
#include <string>
#include <unistd.h>

#include "core/image.h"
#include "storyboard/codec.h"
#include "storyboard/example.h"
#include "storyboard/legend.h"

namespace throng::test {

inline constexpr Rgba8 kWhite{255, 255, 255, 255};
inline constexpr Rgba8 kOrange{255, 128, 0, 255};
inline constexpr Rgba8 kRed{255, 0, 0, 255};
inline constexpr Rgba8 kGreen{0, 200, 0, 255};
inline constexpr Rgba8 kBlue{0, 0, 255, 255};

inline ImageRgba8 exampleStoryboard(int size, uint64_t seed, double density = 10.0) {
  storyboard::ExampleOptions options;
  options.width = options.height = size;
  options.seed = seed;
  options.density = density;
  return storyboard::encodeStoryboard(size, size, storyboard::generateExampleGlyphs(options), storyboard::Legend{});
}

// Draws centre + the outer pixels whose reading-order codes make up `sum`.
inline void drawSum(ImageRgba8& image, int x, int y, int sum, Rgba8 centre, Rgba8 outer) {
  image.at(x, y) = centre;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if ((dx || dy) && (sum & storyboard::outerCode(dx, dy))) image.at(x + dx, y + dy) = outer;
}

// A fresh directory under the system temp folder, removed when the test ends.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
};

}  // namespace throng::test
