// The agents JSON `storyboard encode` reads → Storyboard; when it is small enough to draw
// quickly, encoded as a PNG image and decoded again.
#include "fuzz_support.h"
#include "storyboard/codec.h"
#include "storyboard/storyboard_json.h"

using namespace throng;

namespace {
// Encoding is not the parser under test; big canvases only cost time per input.
constexpr long kMaxEncodedPixels = 256 * 256;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::expectParseOrError([&] {
    const storyboard::Storyboard board =
        storyboard::storyboardFromJson(fuzz::asText(data, size), "fuzz.json");
    if (long(board.width) * long(board.height) > kMaxEncodedPixels) return;
    const storyboard::Legend legend;
    const ImageRgba8 image =
        storyboard::encodeStoryboard(board.width, board.height, board.glyphs, legend);
    storyboard::decodeStoryboard(image, legend);
  });
  return 0;
}
