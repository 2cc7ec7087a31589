// `throng render`'s run: checks, the frame loop and its report (render_run.h).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "core/clock.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/frame_output.h"
#include "core/image.h"
#include "core/log.h"
#include "gpu/commands.h"
#include "limit_option.h"
#include "progress.h"
#include "render/offscreen_target.h"
#include "render_run.h"
#include "scene/frame.h"
#include "scene_file_options.h"
#include "scene_options.h"
#include "scene_storyboard.h"
#include "scene_trajectories.h"
#include "secondary/cloth_gpu_layer.h"
#include "stats.h"

namespace throng::tools {
namespace {

// An output folder with frames of an earlier run is refused unless --overwrite: mixing two
// runs' frames under one numbering is never what anyone wants.
void checkOutputFolder(const std::filesystem::path& dir, bool overwrite) {
  ensureWritableDirectory(dir);
  if (overwrite) return;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("frame_", 0) == 0 && entry.path().extension() == ".png")
      fail(dir.string(), ": holds frames of an earlier run (", name,
           "); use --overwrite or another --out");
  }
}

void printClothSummary(const secondary::ClothLayer& cloth,
                       const std::vector<secondary::ClothTimings>& clothTimes,
                       const std::string& file) {
  auto clothMedian = [&](double secondary::ClothTimings::*field) {
    std::vector<double> values;
    for (const secondary::ClothTimings& t : clothTimes) values.push_back(t.*field);
    return median(values);
  };
  std::vector<double> totals;
  for (const secondary::ClothTimings& t : clothTimes) totals.push_back(t.totalMs());
  secondary::ClothStats s = cloth.stats();
  std::printf(
      "cloth (median, inside render): advance %.2f ms, mark %.2f ms, decode %.2f ms, splat %.2f "
      "ms, "
      "draw %.2f ms; total %.2f ms  [%s]\n",
      clothMedian(&secondary::ClothTimings::advanceMs),
      clothMedian(&secondary::ClothTimings::markMs),
      clothMedian(&secondary::ClothTimings::decodeMs),
      clothMedian(&secondary::ClothTimings::splatMs), clothMedian(&secondary::ClothTimings::drawMs),
      median(totals), file.c_str());
  const secondary::ClothLod& lod = cloth.gpuData().lod;
  std::printf(
      "cloth levels: vertices %u / %u / %u / %u, triangles %u / %u / %u / %u, bases %u / %u / %u / "
      "%u\n",
      lod.levelVertices[0], lod.levelVertices[1], lod.levelVertices[2], lod.levelVertices[3],
      lod.indexCount[0] / 3, lod.indexCount[1] / 3, lod.indexCount[2] / 3, lod.indexCount[3] / 3,
      lod.levelBases[0], lod.levelBases[1], lod.levelBases[2], lod.levelBases[3]);
  std::printf(
      "cloth, last frame: capes per level %u / %u / %u / %u (full … splatted), %u states decoded, "
      "%u demoted\n",
      s.capes[0], s.capes[1], s.capes[2], s.capes[3], s.usedStates, s.demoted);
}

// What is read and checked before the GPU starts.
struct RenderInputs {
  Size size;
  std::filesystem::path outDir;
  std::unique_ptr<secondary::ClothDatabase> clothDb;
  anim::ClipPair clips;
  render::Camera camera;
};

void printRenderTimes(const RenderOptions& o, const RenderInputs& in, const scene::Scene& scene,
                      const gpu::Context& context, const RenderRunTimes& t,
                      const FrameOutputStats& encoded) {
  std::string where = o.pngs ? in.outDir.string() : "";
  if (!o.video.empty()) where += (where.empty() ? "" : " and ") + o.video;
  std::printf("rendered %d frames of %u characters (%u joints each) at %ux%u into %s\n", o.frames,
              scene.count(), scene.synth().jointCount(), in.size.width, in.size.height,
              where.c_str());
  if (scene.steered())
    std::printf(
        "GPU time per frame (median): steering %.2f ms, synthesis %.2f ms, render %.2f ms"
        "  [%s]\n",
        t.steerMs, t.synthesisMs, t.renderMs, context.info().name.c_str());
  else
    std::printf("GPU time per frame (median): synthesis %.2f ms, render %.2f ms  [%s]\n",
                t.synthesisMs, t.renderMs, context.info().name.c_str());
  std::printf("prepared in %.0f ms before the first frame (what a first frame pays once)\n",
              t.prepareMs);
  std::printf(
      "wall time per frame: mean %.2f ms, median %.2f ms; encoding %.2f ms per frame on %d "
      "worker%s, %.2f ms per frame waiting for them\n",
      t.wallMs, t.wallMedianMs, t.encodeMs, t.encodeWorkers, t.encodeWorkers == 1 ? "" : "s",
      encoded.waitedMs / o.frames);
}

// One command buffer, its fence and timestamps, reused frame after frame. A frame submitted and
// not yet waited for is waited for before the submitter goes, however the loop ends (an
// encoder's error thrown while the device runs), so no buffer is freed under the device.
struct FrameSubmitter {
  gpu::Context& context;
  gpu::CommandPool pool;
  VkCommandBuffer cmd;
  gpu::Fence fence;
  gpu::TimestampPool timestamps;
  bool inFlight = false;
  explicit FrameSubmitter(gpu::Context& c)
      : context(c), pool(c), cmd(pool.allocate()), fence(c), timestamps(c, 8) {}
  FrameSubmitter(const FrameSubmitter&) = delete;
  FrameSubmitter& operator=(const FrameSubmitter&) = delete;
  ~FrameSubmitter() {
    if (!inFlight) return;
    try {
      fence.wait();
    } catch (const std::exception&) {
      // A lost device: nothing is left to wait for.
    }
  }
  // Ends and submits the commands recorded into `cmd`.
  void submit() {
    gpu::endCommands(cmd);
    gpu::submit(context, cmd, fence.get());
    inFlight = true;
  }
  // Waits for the submitted commands to complete.
  void wait() {
    fence.wait();
    fence.reset();
    inFlight = false;
  }
};

void submitAndWait(FrameSubmitter& gpu) {
  gpu.submit();
  gpu.wait();
}

// Records and submits one frame with its readback into slot `slot`; its timestamps' marks.
scene::FrameTimestamps submitFrame(FrameSubmitter& gpu, scene::Scene& scene,
                                   const scene::SceneStep& step, render::CrowdRenderer& renderer,
                                   secondary::ClothLayer* cloth,
                                   const scene::FrameSettings& settings,
                                   const render::OffscreenTarget& target, uint32_t slot) {
  gpu.timestamps.reset();
  gpu::beginCommands(gpu.cmd);
  const scene::FrameTimestamps marks = scene::recordFrame(
      gpu.cmd, gpu.context, scene, step, renderer, cloth, settings, gpu.timestamps);
  render::recordReadback(gpu.cmd, target, slot);
  renderer.passTimer().mark(gpu.cmd, "readback");
  gpu.submit();
  return marks;
}

// What the first frame would pay once (scene::FramePreparation and the readback's first
// copy), paid before the frames are timed; its wall milliseconds.
double prepareFrames(FrameSubmitter& gpu, const scene::Scene& scene,
                     render::CrowdRenderer& renderer, const scene::FrameSettings& settings,
                     render::OffscreenTarget& target) {
  const auto start = std::chrono::steady_clock::now();
  const scene::FramePreparation preparation(gpu.context, scene);
  gpu::beginCommands(gpu.cmd);
  preparation.record(gpu.cmd, renderer, settings);
  render::recordReadback(gpu.cmd, target);
  submitAndWait(gpu);
  renderer.passTimer().discardPending();
  return millisecondsSince(start);
}

// What the run left in the scene: goals reached, the motion cache's counters.
void printSceneSummary(const scene::Scene& scene) {
  if (scene.hasGoals())
    std::printf("goals: %u of %u agents reached their final goal%s\n", scene.agentsAtGoal(),
                scene.count(), scene.goalsDone() ? " (all done)" : "");
  if (!scene.synth().cached()) return;
  const synth::MotionCacheStats c = synth::readCacheStats(scene.synth());
  std::printf("motion cache: %u hits, %u misses, %u evictions, %u entries, %.2f of %.2f MB\n",
              c.hits, c.misses, c.evictions, c.entries, c.bytesUsed / 1048576.0,
              c.budgetBytes / 1048576.0);
}

// The frame's settings for the offscreen target: the scene's camera, ground and LOD tint.
scene::FrameSettings offscreenSettings(const RenderOptions& o, const RenderInputs& in,
                                       render::OffscreenTarget& target) {
  scene::FrameSettings settings;
  settings.camera = in.camera;
  settings.targets = render::offscreenFrameTargets(target);
  settings.groundExtent = sceneGroundExtent(o.scene);
  settings.tintLevels = o.scene.lodTint;
  settings.stillView = o.scene.cameraPath.empty();
  return settings;
}

// Where the frames go: PNGs into the output folder and/or a video, encoded off the frame loop.
FrameOutputOptions frameOutputOptions(const RenderOptions& o, const RenderInputs& in) {
  FrameOutputOptions out;
  if (o.pngs) out.pngFolder = in.outDir;
  if (!o.video.empty()) out.video = o.video;
  out.width = int(in.size.width);
  out.height = int(in.size.height);
  out.fps = o.fps > 0.0f ? o.fps : 1.0f / o.scene.dt;
  return out;
}

// Each frame's GPU times and its turn of the frame loop (recording to trajectories written).
struct FrameSeries {
  std::vector<double> steerMs, synthMs, renderMs, turnMs;
  void add(const scene::FrameTimings& t) {
    steerMs.push_back(t.steerMs);
    synthMs.push_back(t.synthesisMs);
    renderMs.push_back(t.renderMs);
  }
};

// What the run reports: medians of the GPU times, wall and encoding per frame.
RenderRunTimes runTimes(uint32_t characters, const FrameSeries& series, double wallMs,
                        const FrameOutputStats& encoded, int frames, double prepareMs) {
  RenderRunTimes times;
  times.prepareMs = prepareMs;
  times.frames = frames;
  times.characters = characters;
  times.steerMs = median(series.steerMs);
  times.synthesisMs = median(series.synthMs);
  times.renderMs = median(series.renderMs);
  times.wallMs = wallMs;
  times.wallMedianMs = median(series.turnMs);
  times.encodeMs = encoded.encodeMs / frames;
  times.encodeWorkers = encoded.workers;
  return times;
}

RenderRunTimes renderFrames(gpu::Context& context, RenderOptions& o, RenderInputs& in) {
  // The scenario's crowd, the steered circle or the storyboard's crowd.
  const std::unique_ptr<scene::Scene> scenePtr = makeScene(context, o.scene, in.clips);
  scene::Scene& scene = *scenePtr;
  render::CrowdRenderer renderer(context, render::kColorFormat, render::kDepthFormat);
  render::OffscreenTarget target =
      render::makeOffscreenTarget(context, in.size.width, in.size.height, /*readbackSlots=*/2);
  scene::FrameSettings settings = offscreenSettings(o, in, target);
  std::unique_ptr<secondary::ClothLayer> cloth;
  if (in.clothDb)
    cloth = std::make_unique<secondary::ClothLayer>(context, *in.clothDb, scene.crowd(),
                                                    render::kColorFormat, render::kDepthFormat,
                                                    sceneClothOptions(o.scene));
  std::vector<secondary::ClothTimings> clothTimes;

  FrameSubmitter gpu(context);
  FrameSeries series;
  FrameOutput output(frameOutputOptions(o, in));  // encodes on workers: off the frame's timing
  SceneTrajectories trajectories(o.scene, scene, uint64_t(o.frames));
  std::optional<Progress> progress;
  // The preparation sees what the first frame will see.
  settings.camera = render::cameraAt(o.scene.cameraPath, 0.0f, in.camera);
  const double prepareMs = prepareFrames(gpu, scene, renderer, settings, target);
  if (o.report) progress.emplace("render", o.frames);
  // A frame's pixels are read out of its readback slot and handed to the encoders while the next
  // frame runs on the device with the other slot: two slots, and still one frame in flight, so
  // nothing the device reads is written by the host while it runs.
  std::optional<int> unread;  // the frame whose pixels wait in slot unread % 2
  auto outputFrame = [&](int frame) {
    ImageRgba8 image = output.spareImage();  // an encoded frame's buffer: no fresh allocation
    render::readbackInto(target, image, uint32_t(frame % 2));
    output.push(std::move(image), frame);
  };
  const auto wallStart = std::chrono::steady_clock::now();
  for (int frame = 0; frame < o.frames; ++frame) {
    const auto turnStart = std::chrono::steady_clock::now();
    settings.camera = render::cameraAt(o.scene.cameraPath, float(frame) * o.scene.dt, in.camera);
    const scene::SceneStep step = scene.advance(o.scene.dt);
    const auto slot = uint32_t(frame % 2);
    settings.targets = render::offscreenFrameTargets(target, slot);  // in place: a slot's image
    const scene::FrameTimestamps marks =
        submitFrame(gpu, scene, step, renderer, cloth.get(), settings, target, slot);
    if (unread) outputFrame(*unread);
    gpu.wait();
    unread = frame;
    const scene::FrameTimings timings = scene::readFrameTimings(gpu.timestamps, marks);
    series.add(timings);
    if (cloth) clothTimes.push_back(cloth->timings(0));
    // Goals: the state machines see arrivals and plan new paths between frames (the device is
    // idle here), every half simulated second.
    if (scene.hasGoals() && (frame + 1) % std::max(1, int(std::lround(0.5f / o.scene.dt))) == 0)
      scene.updateGoals(context);
    trajectories.record(context, scene, double(frame) * o.scene.dt);
    series.turnMs.push_back(millisecondsSince(turnStart));
    char detail[96];
    std::snprintf(detail, sizeof(detail), "synthesis %.2f ms, render %.2f ms",
                  timings.steerMs + timings.synthesisMs, timings.renderMs);
    if (progress) progress->update(frame + 1, detail);
  }
  if (unread) outputFrame(*unread);
  output.finish();
  trajectories.finish();
  if (progress) progress->finish();
  const double wallMs = millisecondsSince(wallStart) / o.frames;
  if (context.validationEnabled() && context.validationMessageCount() > 0)
    fail(context.validationMessageCount(), " Vulkan validation message(s) during the run");
  const FrameOutputStats encoded = output.stats();
  const RenderRunTimes times =
      runTimes(scene.count(), series, wallMs, encoded, o.frames, prepareMs);
  if (!o.report) return times;
  printRenderTimes(o, in, scene, context, times, encoded);
  if (trajectories.enabled())
    std::printf("trajectories of %u agents over %d frames written to %s\n", scene.count(), o.frames,
                o.scene.trajectoriesOut.c_str());
  if (cloth) printClothSummary(*cloth, clothTimes, o.scene.cloth);
  printSceneSummary(scene);
  return times;
}

}  // namespace

RenderOptions defaultRenderOptions() {
  RenderOptions o;
  // The method's defaults: the coverage LOD and the motion cache (--no-lod, --no-cache).
  o.scene.lod = o.scene.cache = true;
  return o;
}

RenderRunTimes runRender(RenderOptions& o) {
  validateSceneOptions(o.scene);
  const bool framesGiven = o.scene.given("--frames") || o.scene.given("--seconds");
  if (o.scene.sceneSeconds > 0.0f && !framesGiven) o.seconds = o.scene.sceneSeconds;
  if (o.seconds > 0.0f) o.frames = int(std::lround(o.seconds / o.scene.dt));
  if (o.frames < 1 || o.frames > 100000) fail("--frames: expected 1..100000, got ", o.frames);
  RenderInputs in;
  in.size = parseSize(o.scene.size);
  in.outDir = o.out;
  if (o.pngs) checkOutputFolder(in.outDir, o.overwrite);
  if (!o.video.empty()) {
    if (o.fps == 0.0f) o.fps = 1.0f / o.scene.dt;
    checkVideoOptions(o.video, {int(in.size.width), int(in.size.height), o.fps});
    if (!o.overwrite && std::filesystem::exists(o.video))
      fail(o.video, ": exists; use --overwrite or another --video");
  }
  // The cloth database is read (and checked) before the GPU starts.
  if (!o.scene.cloth.empty())
    in.clothDb =
        std::make_unique<secondary::ClothDatabase>(secondary::readClothDatabase(o.scene.cloth));
  in.clips = loadSceneClips(o.scene);
  // Capes explored on another skeleton or clip pair would float: refuse them, naming both.
  if (in.clothDb) secondary::checkClothClips(*in.clothDb, o.scene.cloth, in.clips);
  in.camera = sceneCamera(o.scene);
  if (o.report) logInfo(concat("clips: ", in.clips.description));
  if (!o.saveScene.empty()) {
    writeTextFileAtomic(o.saveScene,
                        scene::writeSceneFile(sceneFileOf(o.scene, float(o.frames) * o.scene.dt)));
    logInfo(concat("scene written to ", o.saveScene));
  }

  gpu::ContextOptions contextOptions;
  contextOptions.device = o.scene.device;
  contextOptions.validation = o.validation;
  gpu::Context context(contextOptions);
  checkSceneForDevice(o.scene, context);  // --size and --cache-budget against the limits
  // Past those, what outgrows a limit is the crowd's per-character data.
  RenderRunTimes times;
  namingOption(charactersOption(o.scene), [&] { times = renderFrames(context, o, in); });
  return times;
}

}  // namespace throng::tools
