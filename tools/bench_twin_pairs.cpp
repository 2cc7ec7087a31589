#include "bench_twin_pairs.h"

#include <chrono>
#include <vector>

#include "core/clock.h"
#include "crowd/scenario.h"
#include "stats.h"
#include "synth/cpu_synth.h"
#include "synth/crowd_synth.h"
#include "synthesis_timer.h"
#include "warm_up.h"

namespace throng::tools {

crowd::Crowd benchCrowd(uint32_t characters) {
  crowd::ScenarioOptions options;
  options.characters = characters;
  options.seed = 42;
  return crowd::makeScenario(options);
}

double twinFrameMs(const anim::MotionPair& pair, crowd::Crowd& crowd,
                   std::vector<synth::JointPoint>& joints, unsigned threads) {
  constexpr float kDt = 1.0f / 30.0f;
  const auto start = std::chrono::steady_clock::now();
  synth::stepCrowdCpu(pair, crowd, kDt, threads);
  synth::poseCrowdCpu(pair, crowd, joints, threads);
  return millisecondsSince(start);
}

TwinPairResult benchFullAgainstTwin(const gpu::Context& context,
                                    const synth::SynthPrograms& programs,
                                    const anim::MotionPair& pair, const anim::Skeleton& skeleton,
                                    uint32_t characters, unsigned threads, int pairs, int warmup,
                                    double warmupSeconds) {
  constexpr float kDt = 1.0f / 30.0f;
  // Both start from the same crowd and take the same steps, so each pair's frames are alike.
  const crowd::Crowd gpuCrowd = benchCrowd(characters);
  crowd::Crowd twinCrowd = gpuCrowd;
  const synth::LodOptions everyJoint{false, {}, &skeleton};
  const synth::CrowdSynth synth = synth::makeCrowdSynth(context, pair, gpuCrowd, {}, everyJoint);
  std::vector<synth::JointPoint> joints(size_t(characters) * pair.jointCount());
  SynthesisTimer timer(context);
  InTurn times;  // first the GPU's, then the twin's
  for (WarmUp warmUp(warmup, warmupSeconds); times.pairs() < pairs;) {
    const double gpu = timer.frame(programs, synth, kDt);
    const double twin = twinFrameMs(pair, twinCrowd, joints, threads);
    if (warmUp.measured()) times.add(gpu, twin);
  }
  return {characters,
          threads,
          pairs,
          median(times.first),
          median(times.second),
          spreadOf(times.ratios)};
}

}  // namespace throng::tools
