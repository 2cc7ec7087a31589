#pragma once
// The cloth row of `throng bench`: a whole frame of a caped crowd as `throng render -n N --lod
// --cache --cloth FILE` draws it (synthesis + cloth advance, mark, decode, far-cape splat and
// draw + the joint renderer), medians of GPU timestamps after warm-up, and the cloth passes' own
// times so a reader sees where the frame goes.
#include <string>

#include "gpu/context.h"
#include "secondary/cloth_gpu.h"

namespace throng::tools {

struct ClothBenchOptions {
  std::string cloth;  // .tsc file
  uint32_t characters = 10000;
  std::string size = "1280x720";
  int frames = 20;
  int warmup = 3;
  double warmupSeconds = 0.0;  // and at least this long (WarmUp)
  double targetMs = 50.0;      // the goal for 10,000 caped characters
};

struct ClothBenchResult {
  std::string variant;  // "gpu-lod+cache+cloth-WxH"
  uint32_t characters = 0;
  int frames = 0;
  // Medians over the measured frames (each its own median: the parts need not add up exactly).
  double synthesisMs = 0.0, renderMs = 0.0, frameMs = 0.0;
  double advanceMs = 0.0, markMs = 0.0, decodeMs = 0.0, splatMs = 0.0, drawMs = 0.0, clothMs = 0.0;
  double frameMsMin = 0.0, frameMsMax = 0.0;
  secondary::ClothStats stats;  // the last frame's
};

// Reads the database (Error naming the file when it is bad) and measures.
ClothBenchResult benchCloth(const gpu::Context& context, const ClothBenchOptions& options);

}  // namespace throng::tools
