#pragma once
// Test helper: a scene's frames through scene::recordFrame into an offscreen target (320×180
// unless told), the last one read back. The render tests that compare two ways of drawing the same
// crowd use it.
#include <array>

#include "core/image.h"
#include "gpu/commands.h"
#include "gpu/timestamps.h"
#include "render/offscreen_target.h"
#include "scene/frame.h"

namespace throng::test {

// `frames` steps of 1/30 s seen by `camera`; `transferDst`: the target takes copies (render's
// offscreen path) or not (as the viewer's swapchain, the full-screen resolve); `capes`: worn by
// the scene's crowd (null: none); `readback`: how the target's pixels reach the host.
inline ImageRgba8 renderFrames(gpu::Context& ctx, scene::Scene& scene, const render::Camera& camera,
                               int frames, bool transferDst = true, uint32_t width = 320,
                               uint32_t height = 180, secondary::ClothLayer* capes = nullptr,
                               render::Readback readback = render::Readback::Auto) {
  render::CrowdRenderer renderer(ctx, render::kColorFormat, render::kDepthFormat);
  render::OffscreenTarget target = render::makeOffscreenTarget(ctx, width, height, 1, readback);
  gpu::TimestampPool timestamps(ctx, 8);
  scene::FrameSettings settings;
  settings.camera = camera;
  settings.targets = render::offscreenFrameTargets(target);
  settings.targets.transferDst = transferDst;
  settings.groundExtent = 20.0f;
  for (int f = 0; f < frames; ++f) {
    timestamps.reset();
    const scene::SceneStep step = scene.advance(1 / 30.0f);
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      scene::recordFrame(cmd, ctx, scene, step, renderer, capes, settings, timestamps);
      render::recordReadback(cmd, target);
    });
  }
  return render::readbackImage(target);
}

// One crowd animated by one pair, three frames through the full-screen pass (the swapchain's,
// [0]) and through the splat over the ground's words (the offscreen path, [1]): the ground is
// made when the view comes a second time, then reused.
inline std::array<ImageRgba8, 2> renderBothResolves(gpu::Context& ctx, const crowd::Crowd& crowd,
                                                    const anim::MotionPair& pair,
                                                    const render::Camera& camera,
                                                    const synth::LodOptions& lod,
                                                    uint32_t width = 320, uint32_t height = 180) {
  std::array<ImageRgba8, 2> images;
  for (int copies = 0; copies < 2; ++copies) {
    scene::SceneSetup setup;
    setup.crowd = crowd;
    setup.pairs.push_back(pair);
    setup.groupFirst = {0, uint32_t(crowd.size())};
    scene::Scene scene(ctx, std::move(setup), {}, lod);
    images[copies] = renderFrames(ctx, scene, camera, 3, copies == 1, width, height);
  }
  return images;
}

}  // namespace throng::test
