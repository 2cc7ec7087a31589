#pragma once
// `throng bench`'s render-loop row: the default `throng render` run as it is (3,000 characters,
// LOD + cache, the wide camera, 1280×720, 90 frames, PNGs encoded on workers), into a temporary
// folder that is removed afterwards. Its GPU time per frame next to its wall time per frame.
#include <filesystem>
#include <string>

#include "render_run.h"

namespace throng::tools {

struct RenderLoopBenchOptions {
  std::string device;
  bool quick = false;  // 5 frames of 1000 characters at 320×180 (smoke test)
};

// The folder the row's frames go to (a fresh one inside the system's temporary directory);
// fails with a message when there is no writable temporary directory ($TMPDIR).
std::filesystem::path renderLoopFolder();

RenderRunTimes benchRenderLoop(const RenderLoopBenchOptions& options);

}  // namespace throng::tools
