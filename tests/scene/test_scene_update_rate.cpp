// The update-rate LOD in a scene: a steered scene steers every character from every other's
// place each step, so it refuses the schedule; a plain scene takes it.
#include <doctest/doctest.h>

#include "anim/default_clips.h"
#include "core/error.h"
#include "crowd/scenario.h"
#include "crowd/spatial_order.h"
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

TEST_CASE("scene: numbering in space keeps each character's tint and refuses several groups") {
  crowd::ScenarioOptions options;
  options.characters = 500;
  const crowd::Crowd crowd = crowd::makeScenario(options);
  const anim::ClipPair clips = anim::defaultRunPair();
  scene::SceneSetup setup =
      scene::plainScene(crowd, anim::makeMotionPair(clips.slow, clips.fast), {});
  setup.tints.resize(crowd.size());
  for (uint32_t i = 0; i < setup.tints.size(); ++i) setup.tints[i] = i;
  scene::numberInSpace(setup);
  const std::vector<uint32_t> order = crowd::spatialOrder(crowd);
  CHECK(setup.tints == order);  // character k was character order[k], tint and all
  for (size_t k = 0; k < crowd.size(); ++k)
    REQUIRE(setup.crowd.placement[k] == crowd.placement[order[k]]);
  const std::vector<scene::GroupDescription> groups(2);
  scene::SceneSetup two = scene::groupsScene(groups, 1, 0.0f, {});
  CHECK_THROWS_WITH_AS(scene::numberInSpace(two), doctest::Contains("one group, this one has 2"),
                       Error);
}
