#include "view_scene.h"

#include "core/error.h"

namespace throng::tools {

float groundExtentFor(const crowd::ScenarioOptions& scenario) {
  return 1.6f * crowd::scenarioExtent(scenario) + 40.0f;
}

std::unique_ptr<ViewScene> makeViewScene(const gpu::Context& context, const SceneOptions& options,
                                         anim::ClipPair clips) {
  auto scene = std::make_unique<ViewScene>();
  scene->skeleton = clips.slow.skeleton;
  scene->clipDescription = clips.description;
  scene->pair = anim::makeMotionPair(clips.slow, clips.fast);
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
  crowd::Crowd crowd = makeSceneCrowd(options);  // throws before anything is replaced
  context.waitIdle();
  scene.synth = synth::makeCrowdSynth(context, scene.pair, crowd, cache,
                                      sceneLodOptions(options, scene.skeleton));
  scene.options = options;
  scene.speeds = sceneSpeedSchedule(options);
  scene.groundExtent = groundExtentFor(s);
}

void setLodThresholds(const gpu::Context& context, ViewScene& scene, float midPixels,
                      float nearPixels) {
  if (!(midPixels >= 0.0f && nearPixels >= 0.0f))
    fail("LOD thresholds must be >= 0 pixels, got mid ", midPixels, ", near ", nearPixels);
  scene.options.lodMidPixels = midPixels;
  scene.options.lodNearPixels = nearPixels;
  if (!scene.synth.lod) return;
  context.waitIdle();
  synth::setLodThresholds(scene.synth, scene.skeleton,
                          synth::CoverageThresholds::levels(midPixels, nearPixels));
}

}  // namespace throng::tools
