// PNG bytes → image (stb, through core's readPng) → storyboard glyphs under the default
// legend, strict and not, and the decoded storyboard printed as JSON.
#include "fuzz_support.h"
#include "storyboard/codec.h"
#include "storyboard/storyboard_json.h"

using namespace throng;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::expectParseOrError([&] {
    const fuzz::MemoryFile file({data, size});
    const storyboard::Legend legend;
    const storyboard::Storyboard board = storyboard::readStoryboard(file.path(), legend, false);
    storyboard::storyboardToJson(board);
    storyboard::requireAllValid(board, "fuzz.png");
  });
  return 0;
}
