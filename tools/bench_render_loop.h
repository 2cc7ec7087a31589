#pragma once
// `throng bench`'s render-loop row: the default `throng render` run as it is (3,000 characters,
// LOD + cache, the wide camera, 1280×720, 90 frames, PNGs encoded on workers), into a temporary
// folder that is removed afterwards. Its GPU time per frame next to its wall time per frame.
#include <string>

#include "render_run.h"

namespace throng::tools {

struct RenderLoopBenchOptions {
  std::string device;
  bool quick = false;  // 5 frames of 1000 characters at 320×180 (smoke test)
};

RenderRunTimes benchRenderLoop(const RenderLoopBenchOptions& options);

}  // namespace throng::tools
