#pragma once
// One synthesis frame recorded, submitted and timed with GPU timestamps: the loop body that the
// bench rows and the paper's experiments share.
#include <vector>

#include "anim/reference_synth.h"
#include "gpu/commands.h"
#include "gpu/timestamps.h"
#include "synth/crowd_synth.h"

namespace throng::tools {

// Milliseconds of one synthesis frame and of its passes (each pass over every group).
struct SynthesisPassTimes {
  double total = 0.0, rootMotion = 0.0, coverage = 0.0, cache = 0.0, pose = 0.0;
};

// The median of each pass over frames.
SynthesisPassTimes medianPasses(const std::vector<SynthesisPassTimes>& frames);

class SynthesisTimer {
 public:
  explicit SynthesisTimer(const gpu::Context& context);

  // Runs recordSynthesis once and waits for it; returns its GPU milliseconds.
  double frame(const synth::SynthPrograms& programs, const synth::CrowdSynth& synth, float dt,
               const anim::SpeedRetarget& retarget = {},
               const synth::CoverageCamera* lodCamera = nullptr);
  // The same for a crowd of several groups (programs[k] for group k).
  double frame(std::span<const synth::SynthPrograms* const> programs,
               const synth::CrowdSynth& synth, float dt, const anim::SpeedRetarget& retarget = {},
               const synth::CoverageCamera* lodCamera = nullptr);
  // The passes' times of the frame that the last call ran.
  const SynthesisPassTimes& lastPasses() const { return last_; }

 private:
  const gpu::Context& context_;
  gpu::CommandPool pool_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  gpu::Fence fence_;
  gpu::TimestampPool timestamps_;
  SynthesisPassTimes last_;
};

}  // namespace throng::tools
