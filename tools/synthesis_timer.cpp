#include "synthesis_timer.h"

#include "stats.h"

namespace throng::tools {

SynthesisPassTimes medianPasses(const std::vector<SynthesisPassTimes>& frames) {
  auto of = [&](double SynthesisPassTimes::*field) {
    std::vector<double> v;
    for (const SynthesisPassTimes& t : frames) v.push_back(t.*field);
    return median(v);
  };
  return {of(&SynthesisPassTimes::total), of(&SynthesisPassTimes::rootMotion),
          of(&SynthesisPassTimes::coverage), of(&SynthesisPassTimes::cache),
          of(&SynthesisPassTimes::pose)};
}

SynthesisTimer::SynthesisTimer(const gpu::Context& context)
    : context_(context),
      pool_(context),
      fence_(context),
      timestamps_(context, 2 + synth::kPosePassMarks) {
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
  const bool covered =
      synth::recordRootMotionPasses(cmd_, programs, synth, dt, retarget, lodCamera);
  timestamps_.write(cmd_);
  synth::recordPosePasses(cmd_, programs, synth, context_.info().maxStorageBufferRange, lodCamera,
                          &timestamps_, covered);
  gpu::endCommands(cmd_);
  gpu::submit(context_, cmd_, fence_.get());
  fence_.wait();
  fence_.reset();
  const std::vector<uint64_t> ticks = timestamps_.fetch();
  auto between = [&](uint32_t from) {
    return timestamps_.millisecondsBetween(ticks, from, from + 1);
  };
  last_ = {timestamps_.millisecondsBetween(ticks, 0, 4), between(0), between(1), between(2),
           between(3)};
  return last_.total;
}

}  // namespace throng::tools
