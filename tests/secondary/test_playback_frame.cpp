// Capes in the scene's frame (scene::recordFrame with a ClothLayer): far capes splat into the
// joints' visibility buffer and near ones are drawn in the render pass, and the two resolves of
// that buffer draw the same picture. On a target that takes copies the splat starts from the
// ground's words and visibility_planes.comp splits it into the planes copied in; on any other
// target (the viewer's swapchain) one full-screen fragment pass resolves it.
#include <doctest/doctest.h>

#include <cmath>

#include "anim/default_clips.h"
#include "cloth_fixtures.h"
#include "crowd/scenario.h"
#include "gpu_fixture.h"
#include "render/render_frames.h"
#include "secondary/cloth_gpu_layer.h"

using namespace throng;

namespace {

struct Rendered {
  ImageRgba8 image;
  uint32_t splattedCapes = 0;  // in the last frame
};

// Three frames of 300 characters at the wide camera (nearly every cape small enough to splat), with
// capes or without, through either resolve.
Rendered renderCrowd(const secondary::ClothDatabase* db, bool transferDst) {
  gpu::Context& ctx = test::gpuContext();
  const anim::ClipPair clips = anim::defaultRunPair();
  crowd::ScenarioOptions scenario;
  scenario.characters = 300;
  scenario.seed = 9;
  scene::SceneSetup setup;
  setup.crowd = crowd::makeScenario(scenario);
  setup.pairs.push_back(anim::makeMotionPair(clips.slow, clips.fast));
  setup.groupFirst = {0, scenario.characters};
  scene::Scene scene(ctx, std::move(setup), {}, {});
  std::unique_ptr<secondary::ClothLayer> capes;
  if (db)
    capes = std::make_unique<secondary::ClothLayer>(ctx, *db, scene.crowd(), render::kColorFormat,
                                                    render::kDepthFormat);
  const render::Camera camera = render::cameraPreset("wide", crowd::scenarioExtent(scenario));
  Rendered r;
  r.image = test::renderFrames(ctx, scene, camera, 3, transferDst, 320, 180, capes.get());
  if (capes) r.splattedCapes = capes->stats().capes[gpu_types::kClothSplatLevel];
  return r;
}

}  // namespace

TEST_CASE("frame: capes look the same through the planes pass and the full-screen resolve") {
  gpu::Context& ctx = test::gpuContext();
  if (!render::CrowdRenderer(ctx, render::kColorFormat, render::kDepthFormat).splatSupported()) {
    MESSAGE("SKIPPED: the device cannot splat (64-bit buffer atomics, compute subgroups)");
    return;
  }
  const secondary::PlaybackPrimary primary = test::syntheticPrimary(0.5f, {6, 5, 4});
  const secondary::ClothDatabase db =
      test::randomDatabase(primary, test::syntheticGraph(primary, 3), test::gridMesh(32, 24), 6, 8);
  const ImageRgba8 bare = renderCrowd(nullptr, true).image;
  const Rendered fragment = renderCrowd(&db, false), planes = renderCrowd(&db, true);
  // The capes are there: many pixels differ from the crowd without them.
  const size_t capePixels = size_t(
      std::lround(compareImages(planes.image, bare, 0).fractionDifferent * bare.pixels.size()));
  const ImageDiff diff = compareImages(planes.image, fragment.image, 2);
  MESSAGE("capes splatted ", planes.splattedCapes, ", pixels the capes changed ", capePixels,
          "; planes pass vs full-screen pass: mean ", diff.meanAbsError, ", max ", diff.maxError,
          ", pixels over 2 levels ", diff.fractionDifferent);
  // Far capes take the splat into the visibility buffer. At this size most of their pixels hide
  // behind their wearers: left out of the planes pass, they change a few pixels by up to 149
  // levels, which the bound below does not allow.
  CHECK(planes.splattedCapes > 50);
  CHECK(planes.splattedCapes == fragment.splattedCapes);
  CHECK(capePixels > 500);
  CHECK(diff.maxError <= 2);
  CHECK(diff.meanAbsError < 0.05);
  CHECK(ctx.validationMessageCount() == 0);
}
