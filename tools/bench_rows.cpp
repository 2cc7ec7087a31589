#include "bench_rows.h"

#include "bench_twin_pairs.h"
#include "core/error.h"
#include "crowd/scenario.h"
#include "crowd/spatial_order.h"
#include "gpu/commands.h"
#include "render/camera.h"
#include "render/offscreen_target.h"
#include "scene/frame.h"
#include "scene_options.h"
#include "stats.h"
#include "warm_up.h"

namespace throng::tools {
namespace {
constexpr float kDt = 1.0f / 30.0f;
}  // namespace

Row benchGpuSynthesis(const gpu::Context& context, const synth::SynthPrograms& programs,
                      const anim::MotionPair& pair, const anim::Skeleton& skeleton, uint32_t n,
                      const BenchOptions& o, Variant variant) {
  crowd::Crowd crowd = benchCrowd(n);
  synth::MotionCacheOptions cache{variant >= Variant::LodCache, 0.05f, 20ull << 20};
  if (cache.enabled) anim::quantizeSpeeds(crowd.motion, cache.bucketWidth);
  synth::LodOptions lod{variant != Variant::Full, {}, &skeleton};
  if (variant == Variant::LodCacheRate) {  // as `throng render --lod-update-lag` builds it
    lod.updateLagPixels = o.updateLag;
    crowd = crowd::permuted(crowd, crowd::spatialOrder(crowd));
  }
  synth::CrowdSynth synth = synth::makeCrowdSynth(context, pair, crowd, cache, lod);
  // The default wide camera of `throng render` for this crowd, at 1280x720.
  crowd::ScenarioOptions scenario;
  scenario.characters = n;
  render::Camera view = render::cameraPreset("wide", crowd::scenarioExtent(scenario));
  synth::CoverageCamera camera =
      synth::coverageCamera(view.view(), view.fovYDegrees, 1280, 720, view.nearPlane);
  SynthesisTimer timer(context);
  std::vector<double> ms;
  std::vector<SynthesisPassTimes> passes;
  std::vector<double> moved;
  for (WarmUp warmUp(o.warmup, o.warmupSeconds); int(ms.size()) < o.frames;) {
    double frameMs =
        timer.frame(programs, synth, kDt, {}, variant == Variant::Full ? nullptr : &camera);
    if (!warmUp.measured()) continue;
    ms.push_back(frameMs);
    passes.push_back(timer.lastPasses());
    if (synth.updateRate)  // read after the frame's timestamps: not in its time
      moved.push_back(double(synth::readMovedChunks(context, *synth.updateRate)) /
                      synth.updateRate->chunkCount);
  }
  const char* names[] = {"gpu-synthesis", "gpu-synthesis-lod", "gpu-synthesis-lod+cache",
                         "gpu-synthesis-lod+cache+rate"};
  if (cache.enabled && synth::readCacheStats(synth).bytesUsed > cache.budgetBytes)
    fail("motion cache exceeded its budget");
  return {names[static_cast<int>(variant)],
          n,
          median(ms),
          0.0,
          o.frames,
          medianPasses(passes),
          std::nullopt,
          moved.empty() ? 0.0 : median(moved)};
}

// The slow baseline gets fewer frames at 100,000 characters and more.
int twinFrames(uint32_t n, const BenchOptions& o) {
  return n >= 100000 ? std::max(5, o.frames / 2) : o.frames;
}

Row benchCpuSynthesis(const anim::MotionPair& pair, uint32_t n, unsigned threads,
                      const BenchOptions& o) {
  crowd::Crowd crowd = benchCrowd(n);
  std::vector<synth::JointPoint> joints(size_t(n) * pair.jointCount());
  std::vector<double> ms;
  const int frames = twinFrames(n, o);
  for (int f = 0; f < 1 + frames; ++f) {
    const double frameMs = twinFrameMs(pair, crowd, joints, threads);
    if (f >= 1) ms.push_back(frameMs);
  }
  return {threads == 1 ? "cpu-1-thread" : concat("cpu-", threads, "-threads"), n, median(ms), 0.0,
          frames};
}

// Synthesis and render of `characters` at --size through the scene's frame, seen by the named
// camera preset framed around the crowd, or ("overhead") from above a tenth of its ground.
Row benchRender(const gpu::Context& context, const anim::MotionPair& pair,
                const anim::Skeleton& skeleton, const BenchOptions& o, Variant variant,
                uint32_t characters, const std::string& cameraName) {
  Size size = parseSize(o.size);
  crowd::ScenarioOptions scenario;
  scenario.characters = characters;
  scenario.seed = 42;
  crowd::Crowd crowd = crowd::makeScenario(scenario);
  synth::MotionCacheOptions cache{variant == Variant::LodCache, 0.05f, 20ull << 20};
  if (cache.enabled) anim::quantizeSpeeds(crowd.motion, cache.bucketWidth);
  synth::LodOptions lod{variant != Variant::Full, {}, &skeleton};
  scene::SceneSetup setup;
  setup.pairs.push_back(pair);
  setup.groupFirst = {0, uint32_t(crowd.size())};
  setup.crowd = std::move(crowd);
  const scene::Scene scene(context, std::move(setup), cache, lod);
  render::CrowdRenderer renderer(context, render::kColorFormat, render::kDepthFormat);
  render::OffscreenTarget target = render::makeOffscreenTarget(context, size.width, size.height);
  scene::FrameSettings settings;
  const float extent = crowd::scenarioExtent(scenario);
  settings.camera = cameraName == "overhead"
                        ? render::overheadCamera(extent, 0.1f, float(size.width) / size.height)
                        : render::cameraPreset(cameraName, extent);
  settings.targets = render::offscreenFrameTargets(target);
  gpu::CommandPool pool(context);
  VkCommandBuffer cmd = pool.allocate();
  gpu::Fence fence(context);
  gpu::TimestampPool timestamps(context, 4);
  std::vector<double> synthMs, renderMs;
  for (WarmUp warmUp(o.warmup, o.warmupSeconds); int(renderMs.size()) < o.frames;) {
    timestamps.reset();
    gpu::beginCommands(cmd);
    scene::SceneStep step;
    step.dt = kDt;
    scene::FrameTimestamps marks =
        scene::recordFrame(cmd, context, scene, step, renderer, nullptr, settings, timestamps);
    gpu::endCommands(cmd);
    gpu::submit(context, cmd, fence.get());
    fence.wait();
    fence.reset();
    if (!warmUp.measured()) continue;
    scene::FrameTimings t = scene::readFrameTimings(timestamps, marks);
    synthMs.push_back(t.synthesisMs);
    renderMs.push_back(t.renderMs);
  }
  const char* names[] = {"gpu-synthesis+render-", "gpu-lod+render-", "gpu-lod+cache+render-"};
  const std::string camera = cameraName == "wide" ? "" : cameraName + "-";
  return {concat(names[static_cast<int>(variant)], camera, o.size), characters, median(synthMs),
          median(renderMs), o.frames};
}

}  // namespace throng::tools
