#include "bench_cloth.h"

#include <algorithm>

#include "core/error.h"
#include "gpu/commands.h"
#include "render/offscreen_target.h"
#include "scene/frame.h"
#include "scene_options.h"
#include "scene_storyboard.h"
#include "secondary/cloth_gpu_layer.h"
#include "stats.h"
#include "warm_up.h"

namespace throng::tools {

ClothBenchResult benchCloth(const gpu::Context& context, const ClothBenchOptions& o) {
  if (o.frames < 1 || o.warmup < 0) fail("cloth bench: --frames must be >= 1 and --warmup >= 0");
  // The scene `throng render -n N --lod --cache --cloth FILE` draws: the same defaults (random
  // scenario, wide camera, built-in run pair), so the two print comparable figures.
  SceneOptions scene;
  scene.characters = o.characters;
  scene.lod = true;
  scene.cache = true;
  scene.cloth = o.cloth;
  scene.size = o.size;
  validateSceneOptions(scene);
  const secondary::ClothDatabase db = secondary::readClothDatabase(o.cloth);
  const Size size = parseSize(o.size);
  anim::ClipPair clips = loadSceneClips(scene);
  secondary::checkClothClips(db, o.cloth, clips);  // capes made for this skeleton and these clips
  const std::unique_ptr<scene::Scene> crowd = makeScene(context, scene, clips);
  render::CrowdRenderer renderer(context, render::kColorFormat, render::kDepthFormat);
  render::OffscreenTarget target = render::makeOffscreenTarget(context, size.width, size.height);
  scene::FrameSettings settings;
  settings.camera = sceneCamera(scene);
  settings.targets = render::offscreenFrameTargets(target);
  settings.groundExtent = sceneGroundExtent(scene);
  secondary::ClothLayer cloth(context, db, crowd->crowd(), render::kColorFormat,
                              render::kDepthFormat, sceneClothOptions(scene));

  gpu::CommandPool pool(context);
  VkCommandBuffer cmd = pool.allocate();
  gpu::Fence fence(context);
  gpu::TimestampPool timestamps(context, 8);
  std::vector<double> synthMs, renderMs, frameMs, advance, mark, decode, splat, draw, total;
  for (WarmUp warmUp(o.warmup, o.warmupSeconds); int(frameMs.size()) < o.frames;) {
    timestamps.reset();
    const scene::SceneStep step = crowd->advance(scene.dt);
    gpu::beginCommands(cmd);
    scene::FrameTimestamps marks =
        scene::recordFrame(cmd, context, *crowd, step, renderer, &cloth, settings, timestamps);
    gpu::endCommands(cmd);
    gpu::submit(context, cmd, fence.get());
    fence.wait();
    fence.reset();
    if (!warmUp.measured()) continue;
    const scene::FrameTimings t = scene::readFrameTimings(timestamps, marks);
    const secondary::ClothTimings c = cloth.timings(0);
    synthMs.push_back(t.synthesisMs);
    renderMs.push_back(t.renderMs);
    frameMs.push_back(t.synthesisMs + t.renderMs);
    advance.push_back(c.advanceMs);
    mark.push_back(c.markMs);
    decode.push_back(c.decodeMs);
    splat.push_back(c.splatMs);
    draw.push_back(c.drawMs);
    total.push_back(c.totalMs());
  }
  ClothBenchResult r;
  r.variant = concat("gpu-lod+cache+cloth-", o.size);
  r.characters = o.characters;
  r.frames = o.frames;
  r.synthesisMs = median(synthMs);
  r.renderMs = median(renderMs);
  r.frameMs = median(frameMs);
  r.frameMsMin = *std::min_element(frameMs.begin(), frameMs.end());
  r.frameMsMax = *std::max_element(frameMs.begin(), frameMs.end());
  r.advanceMs = median(advance);
  r.markMs = median(mark);
  r.decodeMs = median(decode);
  r.splatMs = median(splat);
  r.drawMs = median(draw);
  r.clothMs = median(total);
  r.stats = cloth.stats();
  return r;
}

}  // namespace throng::tools
