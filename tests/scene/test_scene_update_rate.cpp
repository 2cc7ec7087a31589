// The update-rate LOD in a scene: a steered scene steers every character from every other's
// place each step, so it refuses the schedule; a plain scene takes it.
#include <doctest/doctest.h>

#include "anim/default_clips.h"
#include "core/error.h"
#include "crowd/scenario.h"
#include "gpu_fixture.h"
#include "scene/scene.h"
#include "scene/scene_builders.h"

using namespace throng;

TEST_CASE("scene: a steered scene refuses the update-rate LOD, a plain one takes it") {
  gpu::Context& ctx = test::gpuContext();
  const anim::ClipPair clips = anim::defaultRunPair();
  const synth::LodOptions lod{true, {}, &clips.slow.skeleton, 2.0f};
  crowd::ScenarioOptions options;
  options.characters = 200;
  options.name = "circle";
  scene::SceneSetup circle = scene::circleScene(crowd::makeScenario(options),
                                                anim::makeMotionPair(clips.slow, clips.fast), {});
  CHECK_THROWS_WITH_AS(scene::Scene(ctx, std::move(circle), {}, lod),
                       doctest::Contains("the update-rate LOD needs an unsteered crowd"), Error);
  options.name = "random";
  const scene::Scene plain(ctx,
                           scene::plainScene(crowd::makeScenario(options),
                                             anim::makeMotionPair(clips.slow, clips.fast), {}),
                           {}, lod);
  REQUIRE(plain.synth().updateRate);
  CHECK(plain.synth().updateRate->chunkCount == 4);
  CHECK(ctx.validationMessageCount() == 0);
}
