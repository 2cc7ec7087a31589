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
    scene->clothDb = std::make_unique<secondary::ClothDatabase>(secondary::readClothDatabase(options.cloth));
  scene->skeleton = clips.slow.skeleton;
  scene->clipDescription = clips.description;
  scene->pair = anim::makeMotionPair(clips.slow, clips.fast);
  if (!options.slowClip.empty()) scene->userClips = clips;  // the storyboard scene's pair for every action
  scene->programs = std::make_unique<synth::SynthPrograms>(context, scene->pair);
  respawnCrowd(context, *scene, options);
  return scene;
}

void respawnCrowd(const gpu::Context& context, ViewScene& scene, const SceneOptions& options) {
  const crowd::ScenarioOptions& s = options.scenario;
  if (s.characters < 1 || s.characters > 4000000)
    fail("characters: expected 1..4000000, got ", s.characters);
  synth::MotionCacheOptions cache = sceneCacheOptions(options);
  synth::validateCacheOptions(cache);
  // Everything that may throw comes before anything is replaced.
  crowd::Crowd crowd;
  std::unique_ptr<render::SteeredCrowdSetup> story;
  if (options.storyboard()) {
    story = std::make_unique<render::SteeredCrowdSetup>(
        makeStoryboardSetup(options, scene.userClips ? &*scene.userClips : nullptr));
  } else {
    crowd = makeSceneCrowd(options);
  }
  context.waitIdle();
  scene.cloth.reset();  // it refers to the old crowd's buffers
  scene.steered.reset();
  scene.synth = {};
  if (story)
    scene.steered = std::make_unique<render::SteeredCrowd>(context, std::move(*story), cache,
                                                           sceneLodOptions(options, scene.skeleton));
  else
    scene.synth = synth::makeCrowdSynth(context, scene.pair, crowd, cache, sceneLodOptions(options, scene.skeleton));
  scene.options = options;
  scene.speeds = sceneSpeedSchedule(options);
  scene.groundExtent = sceneGroundExtent(options);
  if (scene.clothDb)
    scene.cloth = std::make_unique<secondary::ClothLayer>(context, *scene.clothDb,
                                                          scene.steered ? scene.steered->crowd() : scene.synth.crowd,
                                                          scene.colorFormat,
                                                          render::kDepthFormat, sceneClothOptions(options));
}

void setLodThresholds(const gpu::Context& context, ViewScene& scene, float midPixels,
                      float nearPixels) {
  if (!(midPixels >= 0.0f && nearPixels >= 0.0f))
    fail("LOD thresholds must be >= 0 pixels, got mid ", midPixels, ", near ", nearPixels);
  scene.options.lodMidPixels = midPixels;
  scene.options.lodNearPixels = nearPixels;
  if (!frameSynth(scene).lod) return;
  context.waitIdle();
  const synth::CoverageThresholds thresholds = synth::CoverageThresholds::levels(midPixels, nearPixels);
  if (scene.steered) scene.steered->setLodThresholds(scene.skeleton, thresholds);
  else synth::setLodThresholds(scene.synth, scene.skeleton, thresholds);
}

}  // namespace throng::tools
