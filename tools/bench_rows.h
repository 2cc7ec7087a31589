#pragma once
// The bench's rows: what each measures and how (tools/cmd_bench.cpp runs and prints them).
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "anim/motion_texture.h"
#include "anim/skeleton.h"
#include "gpu/context.h"
#include "render_run.h"
#include "synth/synth_jobs.h"
#include "synthesis_timer.h"

namespace throng::tools {

// `throng bench`'s options.
struct BenchOptions {
  std::string json;
  std::vector<uint32_t> counts{1000, 10000, 100000};
  int frames = 20;
  int warmup = 3;
  double warmupSeconds = 0.5;  // and at least this long (a GPU's clocks rise with load)
  uint32_t renderCharacters = 10000;
  uint32_t clipSetCharacters = 8000;  // the storyboard-crowd row
  std::string size = "1280x720";
  std::string device;
  bool quick = false;
  std::string experiments;  // directory for the paper's experiments (CSV + PNG); empty: skip
  std::string cloth;        // .tsc for the caped-crowd row; empty: the row is skipped (said so)
  bool clothOnly = false;   // only the caped-crowd row (seconds instead of a minute)
  // Which kinds of row run (kRowKinds); empty: all.
  std::vector<std::string> rows;
  std::vector<uint32_t> frameCounts{100000, 1000000};  // the whole-frame rows
  float updateLag = 2.0f;  // pixels: the lod+cache+rate rows' update-rate LOD
  bool wants(const std::string& kind) const {
    return rows.empty() || std::find(rows.begin(), rows.end(), kind) != rows.end();
  }
};

// One measured row of the table (and of --json's results).
struct Row {
  std::string variant;
  uint32_t characters = 0;
  double synthesisMs = 0.0;
  double renderMs = 0.0;  // 0 when the variant does not render
  int frames = 0;
  std::optional<SynthesisPassTimes> passes;  // GPU synthesis rows: median of each pass
  std::optional<RenderRunTimes> loop;        // the render-loop row: wall time and encoding
  double movedShare = 0.0;  // the update-rate LOD's rows: median share of chunks moved per step
};

enum class Variant { Full, Lod, LodCache, LodCacheRate };

Row benchGpuSynthesis(const gpu::Context& context, const synth::SynthPrograms& programs,
                      const anim::MotionPair& pair, const anim::Skeleton& skeleton, uint32_t n,
                      const BenchOptions& o, Variant variant);

// The slow baseline gets fewer frames at 100,000 characters and more.
int twinFrames(uint32_t n, const BenchOptions& o);

Row benchCpuSynthesis(const anim::MotionPair& pair, uint32_t n, unsigned threads,
                      const BenchOptions& o);

// Synthesis and render of `characters` at --size through the scene's frame, seen by the named
// camera preset framed around the crowd, or ("overhead") from above a tenth of its ground.
Row benchRender(const gpu::Context& context, const anim::MotionPair& pair,
                const anim::Skeleton& skeleton, const BenchOptions& o, Variant variant,
                uint32_t characters, const std::string& cameraName = "wide");

}  // namespace throng::tools
