#pragma once
// A `throng render` run: the options, their checks, the frame loop (synthesis + draw on the GPU,
// the image read back and encoded off the loop) and its times. `throng render` runs it and
// prints its report; `throng bench` runs the default one for its render-loop row.
#include <cstdint>
#include <string>

#include "scene_options.h"

namespace throng::tools {

struct RenderOptions {
  SceneOptions scene;
  int frames = 90;
  float seconds = 0.0f;  // > 0: frames = seconds / dt
  std::string out = "frames";
  bool pngs = true;  // false with --video and no --out
  std::string video;
  float fps = 0.0f;  // 0: 1 / dt
  bool overwrite = false;
  bool validation = false;
  std::string saveScene;  // also write the scene as a scene file
  bool report = true;     // false: no progress and no printed report (the bench prints its row)
};

// The run's medians of GPU time per frame, its wall time per frame (the mean: from the first
// frame's recording to the last frame encoded, the encoders' drain included; the median: one
// frame loop's turn, recording to the frame handed to the encoders), the encoders' time and the
// preparation before the first frame (what a first frame pays once: scene::FramePreparation).
struct RenderRunTimes {
  int frames = 0;
  uint32_t characters = 0;
  double steerMs = 0.0, synthesisMs = 0.0, renderMs = 0.0;
  double wallMs = 0.0;
  double wallMedianMs = 0.0;
  double encodeMs = 0.0;  // per frame, summed over the workers
  int encodeWorkers = 0;
  double prepareMs = 0.0;  // wall milliseconds, once
  double gpuMs() const { return steerMs + synthesisMs + renderMs; }
};

// The options with `throng render`'s defaults (the coverage LOD and the motion cache on).
RenderOptions defaultRenderOptions();

// Checks the options and inputs, then renders o.frames frames. Fails (throng::Error) on bad
// options or inputs before anything is written.
RenderRunTimes runRender(RenderOptions& o);

}  // namespace throng::tools
