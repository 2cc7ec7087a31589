// A steered scene in the frame (scene::Scene through scene::recordFrame's stages): steering
// before root motion moves walkers along their path vectors, standing pairs stay, several
// motion pairs (groups over one set of buffers) draw as one crowd, and tints colour them.
#include <doctest/doctest.h>

#include <array>
#include <cmath>

#include "anim/default_clips.h"
#include "core/error.h"
#include "core/math.h"
#include "crowd/scenario.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "render/offscreen_target.h"
#include "scene/frame.h"

using namespace throng;

namespace {

// `walkers` agents 6 m apart along x facing +z, then `talkers`; every walker follows one
// straight source at 1.2 m/s. Walkers use the walk pair, talkers the idle/talk pair (or all
// the walk pair with `onePair`).
scene::SceneSetup lineSetup(uint32_t walkers, uint32_t talkers, bool onePair) {
  scene::SceneSetup s;
  s.steering.emplace();
  const uint32_t n = walkers + talkers;
  s.crowd.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    s.crowd.placement[i] = glm::vec4(6.0f * float(i) - 20.0f, 0.0f, 0.0f, 0.0f);
    s.crowd.motion[i] = glm::vec4(0.1f * float(i), 0.3f, 0.3f, 1.0f);
  }
  crowd::PathSource source;
  source.vectors.assign(12, glm::vec2(0.0f, 1.2f));
  std::vector<crowd::PathSource> sources{source};
  s.steering->paths = crowd::followSources(s.crowd, sources, std::vector<uint32_t>(n, 0),
                                           std::vector<float>(n, 2.0f));
  for (uint32_t i = walkers; i < n; ++i) s.steering->paths.lastSecond[i] = 0;  // never steer
  s.tints.assign(n, 0);
  for (uint32_t i = walkers; i < n; ++i) s.tints[i] = 1;
  anim::ClipPair walk = anim::defaultWalkPair();
  s.pairs.push_back(anim::makeMotionPair(walk.slow, walk.fast));
  if (onePair || talkers == 0) {
    s.groupFirst = {0, n};
  } else {
    anim::ClipPair talk = anim::defaultTalkPair();
    s.pairs.push_back(anim::makeMotionPair(talk.slow, talk.fast));
    s.groupFirst = {0, walkers, n};
  }
  return s;
}

struct Rendered {
  std::vector<glm::vec4> placement, motion;
  ImageRgba8 image;
};

// `prepared`: scene::FramePreparation runs first, and the view is still (its ground made then).
Rendered run(scene::Scene& steered, int frames, float dt, const render::Camera& camera,
             uint32_t width, uint32_t height, bool prepared = false) {
  gpu::Context& ctx = test::gpuContext();
  render::CrowdRenderer renderer(ctx, render::kColorFormat, render::kDepthFormat);
  render::OffscreenTarget target = render::makeOffscreenTarget(ctx, width, height);
  scene::FrameSettings settings;
  settings.camera = camera;
  settings.targets = render::offscreenFrameTargets(target);
  settings.groundExtent = 60.0f;
  settings.stillView = prepared;
  gpu::TimestampPool timestamps(ctx, 8);
  if (prepared) {
    const scene::FramePreparation preparation(ctx, steered);
    gpu::submitAndWait(ctx,
                       [&](VkCommandBuffer cmd) { preparation.record(cmd, renderer, settings); });
  }
  for (int f = 0; f < frames; ++f) {
    timestamps.reset();
    const scene::SceneStep step = steered.advance(dt);
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      scene::recordFrame(cmd, ctx, steered, step, renderer, nullptr, settings, timestamps);
      render::recordReadback(cmd, target);
    });
  }
  Rendered r;
  r.placement = gpu::readback<glm::vec4>(ctx, steered.crowd().placement, steered.count());
  r.motion = gpu::readback<glm::vec4>(ctx, steered.crowd().motion, steered.count());
  r.image = render::readbackImage(target);
  CHECK(ctx.validationMessageCount() == 0);
  return r;
}

bool finite(glm::vec4 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

}  // namespace

TEST_CASE(
    "steered scene: walkers follow their path vectors through root motion, talkers stand, nothing "
    "is NaN") {
  for (bool onePair : {false, true}) {
    CAPTURE(onePair);
    const uint32_t walkers = 5, talkers = 2;
    scene::SceneSetup setup = lineSetup(walkers, talkers, onePair);
    const std::vector<glm::vec4> start = setup.crowd.placement;
    scene::Scene steered(test::gpuContext(), std::move(setup), {}, {});
    CHECK(steered.groupCount() == (onePair ? 1u : 2u));
    CHECK(steered.count() == walkers + talkers);
    render::Camera camera = render::cameraPreset("top", 25.0f);
    Rendered r = run(steered, 60, 1.0f / 30.0f, camera, 96, 54);  // two simulated seconds
    CHECK(steered.seconds() == doctest::Approx(2.0));
    for (uint32_t i = 0; i < walkers + talkers; ++i) {
      CAPTURE(i);
      REQUIRE(finite(r.placement[i]));
      REQUIRE(finite(r.motion[i]));
      CHECK(r.motion[i].z >= 0.0f);
      CHECK(r.motion[i].z <= 1.0f);
      const glm::vec2 moved(r.placement[i].x - start[i].x, r.placement[i].z - start[i].z);
      if (i < walkers || onePair) {
        // Along +z at about the path's 1.2 m/s (the walk pair moves at 1.0 to 1.6 m/s; w
        // changes at cycle ends), without drifting sideways.
        CHECK(moved.y > 1.8f);
        CHECK(moved.y < 3.4f);
        CHECK(std::abs(moved.x) < 0.3f);
        CHECK(std::abs(r.placement[i].w) < 0.2f);  // still heading +z
      } else {
        CHECK(glm::length(moved) < 0.05f);  // the idle/talk pair does not travel
      }
    }
  }
}

// Mean colour (normalized RGB) of the characters drawn in the left and right halves.
std::array<glm::vec3, 2> sideColours(const ImageRgba8& image) {
  const Rgba8 background = image.at(image.width / 2, 2);
  glm::vec3 sum[2] = {glm::vec3(0.0f), glm::vec3(0.0f)};
  int count[2] = {0, 0};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const Rgba8 p = image.at(x, y);
      if (std::abs(int(p.r) - int(background.r)) + std::abs(int(p.g) - int(background.g)) +
              std::abs(int(p.b) - int(background.b)) <
          60)
        continue;
      const int side = x < image.width / 2 ? 0 : 1;
      sum[side] += glm::vec3(p.r, p.g, p.b);
      ++count[side];
    }
  REQUIRE(count[0] > 20);
  REQUIRE(count[1] > 20);
  return {glm::normalize(sum[0] / float(count[0])), glm::normalize(sum[1] / float(count[1]))};
}

TEST_CASE("steered scene: each group gets its own colour, several pairs draw as one crowd") {
  // Two groups (one per motion pair) far apart seen from above: two hues; with one group
  // for all, one hue (so the colour comes from the group, not from the character).
  render::Camera camera;
  camera.eye = {0.0f, 12.0f, -0.01f};
  camera.target = {0.0f, 0.0f, 0.0f};
  std::array<glm::vec3, 2> colours[2];
  for (int sameGroup = 0; sameGroup < 2; ++sameGroup) {
    scene::SceneSetup setup = lineSetup(4, 4, false);
    for (uint32_t i = 0; i < 8; ++i)
      setup.crowd.placement[i] =
          glm::vec4(i < 4 ? -4.0f : 4.0f, 0.0f, 1.5f * float(i % 4) - 2.25f, 0.0f);
    crowd::PathSource still;
    still.vectors.assign(4, glm::vec2(0.0f, 0.0f));
    std::vector<crowd::PathSource> sources{still};
    setup.steering->paths = crowd::followSources(setup.crowd, sources, std::vector<uint32_t>(8, 0),
                                                 std::vector<float>(8, 1.0f));
    if (sameGroup) setup.tints.assign(8, 3);
    scene::Scene steered(test::gpuContext(), std::move(setup), {}, {});
    colours[sameGroup] = sideColours(run(steered, 2, 1.0f / 30.0f, camera, 128, 96).image);
  }
  const glm::vec3 a = colours[0][0], b = colours[0][1];
  MESSAGE("two groups, normalized mean RGB: ", a.x, " ", a.y, " ", a.z, " vs ", b.x, " ", b.y, " ",
          b.z);
  CHECK(glm::dot(a, b) < 0.97f);                           // clearly different hues
  CHECK(glm::dot(colours[1][0], colours[1][1]) > 0.995f);  // one group: one hue on both sides
}

TEST_CASE("steered scene: inconsistent setups are refused") {
  scene::SceneSetup setup = lineSetup(3, 2, false);
  SUBCASE("ranges that leave agents out") {
    setup.groupFirst = {0, 3, 4};
    CHECK_THROWS_WITH_AS(scene::Scene(test::gpuContext(), std::move(setup), {}, {}),
                         doctest::Contains("groups must run from 0 to the 5 characters"), Error);
  }
  SUBCASE("a pair without agents") {
    setup.groupFirst = {0, 5, 5};
    CHECK_THROWS_WITH_AS(scene::Scene(test::gpuContext(), std::move(setup), {}, {}),
                         doctest::Contains("group 1 has no character"), Error);
  }
  SUBCASE("too few tints") {
    setup.tints.pop_back();
    CHECK_THROWS_WITH_AS(scene::Scene(test::gpuContext(), std::move(setup), {}, {}),
                         doctest::Contains("tints"), Error);
  }
  SUBCASE("too few paths") {
    setup.steering->paths.source.pop_back();
    CHECK_THROWS_WITH_AS(scene::Scene(test::gpuContext(), std::move(setup), {}, {}),
                         doctest::Contains("paths"), Error);
  }
}

TEST_CASE("scene: the preparation before the first frame moves nothing") {
  // With the coverage LOD and the motion cache on, a run prepared with scene::FramePreparation
  // ends where an unprepared one does and draws the same pictures: it only pays the first
  // frame's one-time costs early. Steered: the line of walkers from above. Unsteered: 500
  // runners at the street camera, near and far, with the update-rate LOD (which needs an
  // unsteered crowd). There levels change at the runners' cycle ends once their timers allow:
  // masks left as the preparation moved them (its coverage pass starts their timers one frame
  // early) change 255 pixels of the last frame.
  const anim::ClipPair walk = anim::defaultWalkPair(), runPair = anim::defaultRunPair();
  synth::MotionCacheOptions cache;
  cache.enabled = true;
  crowd::ScenarioOptions scenario;
  scenario.characters = 500;
  scenario.seed = 7;
  for (bool steeredScene : {true, false}) {
    CAPTURE(steeredScene);
    const synth::LodOptions lod{true,
                                {},
                                steeredScene ? &walk.slow.skeleton : &runPair.slow.skeleton,
                                steeredScene ? 0.0f : 2.0f};
    const render::Camera camera =
        steeredScene ? render::cameraPreset("top", 25.0f)
                     : render::cameraPreset("street", crowd::scenarioExtent(scenario));
    Rendered runs[2];
    glm::vec4 start(0.0f);
    for (int prepared = 0; prepared < 2; ++prepared) {
      CAPTURE(prepared);
      scene::SceneSetup setup = lineSetup(6, 0, true);
      if (!steeredScene) {
        setup = scene::SceneSetup{};
        setup.crowd = crowd::makeScenario(scenario);
        setup.pairs.push_back(anim::makeMotionPair(runPair.slow, runPair.fast));
        setup.groupFirst = {0, scenario.characters};
      }
      start = setup.crowd.placement[0];
      scene::Scene scene(test::gpuContext(), std::move(setup), cache, lod);
      runs[prepared] = run(scene, 20, 1.0f / 30.0f, camera, 800, 450, prepared == 1);
      CHECK(scene.seconds() == doctest::Approx(20.0 / 30.0));
    }
    size_t placementsDiffer = 0, motionsDiffer = 0;
    for (uint32_t i = 0; i < runs[0].placement.size(); ++i) {
      placementsDiffer += runs[1].placement[i] != runs[0].placement[i];
      motionsDiffer += runs[1].motion[i] != runs[0].motion[i];
    }
    CHECK(placementsDiffer == 0);
    CHECK(motionsDiffer == 0);
    REQUIRE(runs[1].image.pixels.size() == runs[0].image.pixels.size());
    size_t differing = 0;
    for (size_t p = 0; p < runs[0].image.pixels.size(); ++p)
      differing += runs[1].image.pixels[p] != runs[0].image.pixels[p];
    CHECK(differing == 0);
    // The characters moved: the comparison is between two runs that did something.
    CHECK(glm::length(glm::vec2(runs[0].placement[0].x - start.x,
                                runs[0].placement[0].z - start.z)) > 0.2f);
  }
}
