#include "view_scene.h"

#include "core/error.h"
#include "render/offscreen_target.h"
#include "scene_storyboard.h"

namespace throng::tools {

std::unique_ptr<ViewScene> makeViewScene(const gpu::Context& context, const SceneOptions& options,
                                         anim::ClipPair clips, VkFormat colorFormat) {
  auto scene = std::make_unique<ViewScene>();
  scene->colorFormat = colorFormat;
  if (!options.cloth.empty())
    scene->clothDb =
        std::make_unique<secondary::ClothDatabase>(secondary::readClothDatabase(options.cloth));
  if (scene->clothDb) secondary::checkClothClips(*scene->clothDb, options.cloth, clips);
  scene->skeleton = clips.slow.skeleton;
  scene->clipDescription = clips.description;
  scene->clips = std::move(clips);
  respawnCrowd(context, *scene, options);
  return scene;
}

namespace {

// The CPU side of a crowd: everything that may throw before the GPU crowd is replaced.
scene::SceneSetup prepareCrowd(const ViewScene& scene, const SceneOptions& options) {
  const crowd::ScenarioOptions& s = options.scenario;
  if (s.characters < 1 || s.characters > 4000000)
    fail("characters: expected 1..4000000, got ", s.characters);
  validateSceneCacheOptions(options);
  return makeSceneSetup(options, scene.clips);
}

// Replaces the GPU crowd (the GPU is idle); may throw part way, e.g. past a device limit.
void installCrowd(const gpu::Context& context, ViewScene& scene, const SceneOptions& options,
                  scene::SceneSetup& prepared) {
  scene.cloth.reset();  // it refers to the old crowd's buffers
  scene.crowd.reset();
  scene.crowd =
      std::make_unique<scene::Scene>(context, std::move(prepared), sceneCacheOptions(options),
                                     sceneLodOptions(options, scene.skeleton));
  scene.options = options;
  scene.groundExtent = sceneGroundExtent(options);
  if (scene.clothDb)
    scene.cloth = std::make_unique<secondary::ClothLayer>(
        context, *scene.clothDb, scene.crowd->crowd(), scene.colorFormat, render::kDepthFormat,
        sceneClothOptions(options));
}

}  // namespace

void respawnCrowd(const gpu::Context& context, ViewScene& scene, const SceneOptions& options) {
  scene::SceneSetup next = prepareCrowd(scene, options);
  const bool hadCrowd = scene.crowd != nullptr;
  const SceneOptions previous = scene.options;
  context.waitIdle();
  try {
    installCrowd(context, scene, options, next);
  } catch (const Error&) {
    // The old crowd's buffers are gone: rebuild it as it was spawned (it fitted before).
    if (hadCrowd) {
      scene::SceneSetup old = prepareCrowd(scene, previous);
      installCrowd(context, scene, previous, old);
    }
    throw;
  }
}

void setLodThresholds(const gpu::Context& context, ViewScene& scene, float midPixels,
                      float nearPixels) {
  if (!(midPixels >= 0.0f && nearPixels >= 0.0f))
    fail("LOD thresholds must be >= 0 pixels, got mid ", midPixels, ", near ", nearPixels);
  scene.options.lodMidPixels = midPixels;
  scene.options.lodNearPixels = nearPixels;
  if (!frameSynth(scene).lod) return;
  context.waitIdle();
  const synth::CoverageThresholds thresholds =
      synth::CoverageThresholds::levels(midPixels, nearPixels);
  scene.crowd->setLodThresholds(scene.skeleton, thresholds);
}

}  // namespace throng::tools
