// Legend JSON → Legend, then the legend in use: every named group's colour, the first unnamed
// groups' colours, and a small built-in storyboard encoded with the default legend decoded
// under the fuzzed one.
#include "fuzz_support.h"
#include "storyboard/codec.h"
#include "storyboard/example.h"
#include "storyboard/legend.h"

using namespace throng;

namespace {
const throng::ImageRgba8& sampleBoard() {
  static const throng::ImageRgba8 image = [] {
    storyboard::ExampleOptions options;
    options.width = 24;
    options.height = 24;
    const auto glyphs = storyboard::generateExampleGlyphs(options);
    return storyboard::encodeStoryboard(options.width, options.height, glyphs,
                                        storyboard::Legend{});
  }();
  return image;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const ImageRgba8& image = sampleBoard();
  fuzz::expectParseOrError([&] {
    const storyboard::Legend legend =
        storyboard::parseLegend(fuzz::asText(data, size), "fuzz.json");
    const int named = int(legend.groups.size());
    for (int group = 0; group < named + 3; ++group) {
      try {
        storyboard::groupColour(legend, group);
      } catch (const Error& e) {  // palette exhausted: a clear error, as documented
        if (fuzz::isInternalCheck(e.what())) throw;
      }
    }
    storyboard::decodeStoryboard(image, legend);
  });
  return 0;
}
