// `throng render`: headless frame dumps of a crowd (synthesis + draw on the GPU, PNG files).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <future>
#include <memory>

#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/image.h"
#include "core/log.h"
#include "gpu/commands.h"
#include "render/crowd_frame.h"
#include "render/offscreen_target.h"
#include "scene_options.h"
#include "stats.h"

namespace throng::tools {
namespace {

struct RenderOptions {
  SceneOptions scene;
  int frames = 90;
  std::string out = "frames";
  bool validation = false;
};

void runRender(RenderOptions& o) {
  validateSceneOptions(o.scene);
  if (o.frames < 1 || o.frames > 100000) fail("--frames: expected 1..100000, got ", o.frames);
  Size size = parseSize(o.scene.size);
  std::filesystem::path outDir = o.out;
  ensureWritableDirectory(outDir);

  anim::ClipPair clips = loadSceneClips(o.scene);
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  crowd::Crowd crowd = makeSceneCrowd(o.scene);
  synth::SpeedSchedule speeds = sceneSpeedSchedule(o.scene);
  render::Camera camera = sceneCamera(o.scene);
  logInfo(concat("clips: ", clips.description));

  gpu::ContextOptions contextOptions;
  contextOptions.device = o.scene.device;
  contextOptions.validation = o.validation;
  gpu::Context context(contextOptions);
  synth::SynthPrograms programs(context, pair);
  render::CrowdRenderer renderer(context, render::kColorFormat, render::kDepthFormat);
  render::OffscreenTarget target = render::makeOffscreenTarget(context, size.width, size.height);
  synth::CrowdSynth synth = synth::makeCrowdSynth(context, pair, crowd, sceneCacheOptions(o.scene),
                                                  sceneLodOptions(o.scene, clips.slow.skeleton));
  render::FrameTargets targets{target.color.get(), target.color.view(), target.depth.get(), target.depth.view(),
                               size.width, size.height, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
  const float groundExtent = 1.6f * crowd::scenarioExtent(o.scene.scenario) + 40.0f;

  gpu::CommandPool pool(context);
  VkCommandBuffer cmd = pool.allocate();
  gpu::Fence fence(context);
  gpu::TimestampPool timestamps(context, 8);
  std::vector<double> synthMs, renderMs;
  std::future<void> pendingWrite;
  for (int frame = 0; frame < o.frames; ++frame) {
    timestamps.reset();
    gpu::beginCommands(cmd);
    render::FrameTimestamps marks = render::recordCrowdFrame(cmd, context, programs, synth, renderer, camera,
                                                             groundExtent, targets, o.scene.dt, timestamps, 0, speeds.advance(o.scene.dt),
                                                             o.scene.lodTint);
    render::recordReadback(cmd, target);
    gpu::endCommands(cmd);
    gpu::submit(context, cmd, fence.get());
    fence.wait();
    fence.reset();
    render::FrameTimings timings = render::readFrameTimings(timestamps, marks);
    synthMs.push_back(timings.synthesisMs);
    renderMs.push_back(timings.renderMs);
    if (pendingWrite.valid()) pendingWrite.get();  // at most one PNG encoding in flight
    auto image = std::make_shared<ImageRgba8>(render::readbackImage(target));
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04d.png", frame);
    pendingWrite = std::async(std::launch::async, [image, path = outDir / name] { writePngAtomic(path, *image); });
    if (o.frames >= 10 && (frame + 1) % std::max(1, o.frames / 10) == 0)
      logInfo(concat("frame ", frame + 1, "/", o.frames, "  synthesis ", timings.synthesisMs, " ms, render ",
                     timings.renderMs, " ms"));
  }
  if (pendingWrite.valid()) pendingWrite.get();
  if (context.validationEnabled() && context.validationMessageCount() > 0)
    fail(context.validationMessageCount(), " Vulkan validation message(s) during the run");
  std::printf("rendered %d frames of %u characters (%u joints each) at %ux%u into %s\n", o.frames, synth.crowd.count,
              synth.jointCount(), size.width, size.height, outDir.string().c_str());
  std::printf("GPU time per frame (median): synthesis %.2f ms, render %.2f ms  [%s]\n", median(synthMs),
              median(renderMs), context.info().name.c_str());
  if (synth.cache.options.enabled) {
    synth::MotionCacheStats c = synth::readCacheStats(synth.cache);
    std::printf("motion cache: %u hits, %u misses, %u evictions, %u entries, %.2f of %.2f MB\n", c.hits, c.misses,
                c.evictions, c.entries, c.bytesUsed / 1048576.0, c.budgetBytes / 1048576.0);
  }
}

void addRenderCommand(CLI::App& app, int&) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a crowd headless and write PNG frames");
  addSceneOptions(*cmd, options->scene);
  cmd->add_option("--frames", options->frames, "Number of frames")->capture_default_str();
  cmd->add_option("--out,-o", options->out, "Output directory (frame_0000.png ...)")->capture_default_str();
  cmd->add_flag("--validation", options->validation, "Enable the Khronos validation layer");
  cmd->callback([options] { runRender(*options); });
}

const CommandRegistration kRegistration("render", addRenderCommand);

}  // namespace
}  // namespace throng::tools
