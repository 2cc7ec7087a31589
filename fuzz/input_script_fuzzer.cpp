// Viewer input scripts (wait, drag, key, scroll, resize, respawn, lod, cache, close) → per-frame
// events.
#include <string>

#include "fuzz_support.h"
#include "viewer/input_script.h"

using namespace throng;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::expectParseOrError(
      [&] { render::parseInputScript(std::string(fuzz::asText(data, size)), "fuzz.script"); });
  return 0;
}
