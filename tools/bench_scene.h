#pragma once
// The bench's storyboard-crowd row: a crowd animated by four clip sets (walk, run, idle/talk and
// hop, in the action mix of the built-in storyboard) as groups over one set of buffers, against
// the same crowd animated by one clip set, both with the coverage LOD and the motion cache,
// frames interleaved in one run so the ratio is measured under the same machine load.
#include <cstdint>

#include "gpu/context.h"
#include "stats.h"
#include "synthesis_timer.h"

namespace throng::tools {

struct ClipSetBenchResult {
  uint32_t characters = 0;
  int frames = 0;
  double oneSetMs = 0.0;                     // synthesis, median
  double fourSetsMs = 0.0;                   // synthesis, median
  Spread ratio;                              // per-frame pairs four / one
  SynthesisPassTimes onePasses, fourPasses;  // medians of each pass
};

// warmup frames, for at least warmupSeconds (WarmUp), before `frames` measured ones.
ClipSetBenchResult benchClipSets(const gpu::Context& context, uint32_t characters, int frames,
                                 int warmup, double warmupSeconds);

}  // namespace throng::tools
