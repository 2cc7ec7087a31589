#include "bench_scene.h"

#include <algorithm>

#include "anim/default_clips.h"
#include "core/error.h"
#include "crowd/scenario.h"
#include "render/camera.h"
#include "scene/scene.h"
#include "stats.h"
#include "synthesis_timer.h"
#include "warm_up.h"

namespace throng::tools {
namespace {

constexpr float kDt = 1.0f / 30.0f;
constexpr float kBucketWidth = 0.05f;

// The built-in storyboard's action mix (assets/storyboards/plaza_small.png quilted): walk 43%,
// run 16%, talk 5%, hop 36%.
constexpr float kActionShare[4] = {0.43f, 0.16f, 0.05f, 0.36f};

std::unique_ptr<scene::Scene> makeBenchScene(const gpu::Context& context, uint32_t n, bool fourSets,
                                             const anim::Skeleton& skeleton) {
  crowd::ScenarioOptions options;
  options.characters = n;
  options.seed = 42;
  scene::SceneSetup setup;
  setup.crowd = crowd::makeScenario(options);
  anim::quantizeSpeeds(setup.crowd.motion, kBucketWidth);
  const anim::ClipPair sets[4] = {anim::defaultWalkPair(), anim::defaultRunPair(),
                                  anim::defaultTalkPair(), anim::defaultJumpPair()};
  setup.groupFirst = {0};
  if (fourSets) {
    float share = 0.0f;
    for (int k = 0; k < 4; ++k) {
      share += kActionShare[k];
      const uint32_t end = k == 3 ? n : std::min(n, uint32_t(share * float(n)));
      if (end <= setup.groupFirst.back()) continue;
      setup.pairs.push_back(anim::makeMotionPair(sets[k].slow, sets[k].fast));
      setup.groupFirst.push_back(end);
    }
  } else {
    setup.pairs.push_back(anim::makeMotionPair(sets[1].slow, sets[1].fast));
    setup.groupFirst.push_back(n);
  }
  synth::MotionCacheOptions cache{true, kBucketWidth, 20ull << 20};
  synth::LodOptions lod{true, {}, &skeleton};
  return std::make_unique<scene::Scene>(context, std::move(setup), cache, lod);
}

}  // namespace

ClipSetBenchResult benchClipSets(const gpu::Context& context, uint32_t n, int frames, int warmup,
                                 double warmupSeconds) {
  if (n == 0 || frames < 1) fail("clip-set bench: needs characters and frames");
  const anim::ClipPair run = anim::defaultRunPair();
  std::unique_ptr<scene::Scene> one = makeBenchScene(context, n, false, run.slow.skeleton);
  std::unique_ptr<scene::Scene> four = makeBenchScene(context, n, true, run.slow.skeleton);
  crowd::ScenarioOptions scenario;
  scenario.characters = n;
  const render::Camera view = render::cameraPreset("wide", crowd::scenarioExtent(scenario));
  const synth::CoverageCamera camera =
      synth::coverageCamera(view.view(), view.fovYDegrees, 1280, 720, view.nearPlane);
  SynthesisTimer timer(context);
  InTurn times;  // first one set's, then four sets'
  std::vector<SynthesisPassTimes> onePasses, fourPasses;
  for (WarmUp warmUp(warmup, warmupSeconds); times.pairs() < frames;) {
    // Interleaved: both see the same moments of machine load.
    const double a = timer.frame(one->programs(), one->synth(), kDt, {}, &camera);
    const SynthesisPassTimes aPasses = timer.lastPasses();
    const double b = timer.frame(four->programs(), four->synth(), kDt, {}, &camera);
    if (!warmUp.measured()) continue;
    onePasses.push_back(aPasses);
    fourPasses.push_back(timer.lastPasses());
    times.add(a, b);
  }
  ClipSetBenchResult r;
  r.characters = n;
  r.frames = frames;
  r.oneSetMs = median(times.first);
  r.fourSetsMs = median(times.second);
  r.ratio = spreadOf(times.ratios);
  r.onePasses = medianPasses(onePasses);
  r.fourPasses = medianPasses(fourPasses);
  return r;
}

}  // namespace throng::tools
