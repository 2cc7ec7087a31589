// Scene file JSON → SceneFile; a file that reads must also write and read back to the same text
// (the writer and reader agree on every value they accept).
#include "fuzz_support.h"
#include "scene/scene_file.h"

using namespace throng;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::expectParseOrError([&] {
    const scene::SceneFile f =
        scene::parseSceneFile(fuzz::asText(data, size), "fuzz.json", "/scenes");
    const std::string text = scene::writeSceneFile(f);
    const scene::SceneFile g = scene::parseSceneFile(text, "written.json", "/scenes");
    if (scene::writeSceneFile(g) != text)
      fuzz::finding("round trip", "a written scene file reads back differently");
  });
  return 0;
}
