#include "synthesis_timer.h"

namespace throng::tools {

SynthesisTimer::SynthesisTimer(const gpu::Context& context)
    : context_(context), pool_(context), fence_(context), timestamps_(context, 2) {
  cmd_ = pool_.allocate();
}

double SynthesisTimer::frame(const synth::SynthPrograms& programs, const synth::CrowdSynth& synth,
                             float dt, const anim::SpeedRetarget& retarget,
                             const synth::CoverageCamera* lodCamera) {
  const synth::SynthPrograms* one[] = {&programs};
  return frame(one, synth, dt, retarget, lodCamera);
}

double SynthesisTimer::frame(std::span<const synth::SynthPrograms* const> programs,
                             const synth::CrowdSynth& synth, float dt,
                             const anim::SpeedRetarget& retarget,
                             const synth::CoverageCamera* lodCamera) {
  timestamps_.reset();
  gpu::beginCommands(cmd_);
  timestamps_.write(cmd_, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
  synth::recordSynthesis(cmd_, programs, synth, dt, context_.info().maxStorageBufferRange, retarget,
                         lodCamera);
  timestamps_.write(cmd_);
  gpu::endCommands(cmd_);
  gpu::submit(context_, cmd_, fence_.get());
  fence_.wait();
  fence_.reset();
  return timestamps_.millisecondsBetween(timestamps_.fetch(), 0, 1);
}

}  // namespace throng::tools
