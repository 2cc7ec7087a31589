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
  ImageRgba8 image;     // the last frame
  ImageRgba8 first;     // the first frame (Start::Prepared)
  ImageRgba8 prepared;  // what the preparation drew (Start::Prepared)
  synth::MotionCacheStats cache;
};

// How a run starts: its view moving, still (its ground made at the first frame), or still and
// prepared first (scene::FramePreparation).
enum class Start { Moving, Still, Prepared };

Rendered run(scene::Scene& steered, int frames, float dt, const render::Camera& camera,
             uint32_t width, uint32_t height, Start start = Start::Moving) {
  gpu::Context& ctx = test::gpuContext();
  render::CrowdRenderer renderer(ctx, render::kColorFormat, render::kDepthFormat);
  render::OffscreenTarget target = render::makeOffscreenTarget(ctx, width, height);
  scene::FrameSettings settings;
  settings.camera = camera;
  settings.targets = render::offscreenFrameTargets(target);
  settings.groundExtent = 60.0f;
  settings.stillView = start != Start::Moving;
  gpu::TimestampPool timestamps(ctx, 8);
  Rendered r;
  if (start == Start::Prepared) {
    const scene::FramePreparation preparation(ctx, steered);
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      preparation.record(cmd, renderer, settings);
      render::recordReadback(cmd, target);
    });
    r.prepared = render::readbackImage(target);
  }
  for (int f = 0; f < frames; ++f) {
    timestamps.reset();
    const scene::SceneStep step = steered.advance(dt);
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      scene::recordFrame(cmd, ctx, steered, step, renderer, nullptr, settings, timestamps);
      render::recordReadback(cmd, target);
    });
    if (f == 0 && start == Start::Prepared) r.first = render::readbackImage(target);
  }
  r.placement = gpu::readback<glm::vec4>(ctx, steered.crowd().placement, steered.count());
  r.motion = gpu::readback<glm::vec4>(ctx, steered.crowd().motion, steered.count());
  r.image = render::readbackImage(target);
  if (steered.synth().cached()) r.cache = synth::readCacheStats(steered.synth());
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
  // ends where an unprepared one does, draws the same pictures and counts the same cache hits:
  // it only pays the first frame's one-time costs early. Steered: walkers and talkers (two clip
  // sets) from above. Unsteered: 500 runners at the street camera, near and far, with the
  // update-rate LOD (which needs an unsteered crowd). There levels change at the runners' cycle
  // ends once their timers allow: masks left as the preparation moved them (its coverage pass
  // starts their timers one frame early) change 255 pixels of the last frame.
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
      scene::SceneSetup setup = lineSetup(5, 2, false);
      if (!steeredScene) {
        setup = scene::SceneSetup{};
        setup.crowd = crowd::makeScenario(scenario);
        setup.pairs.push_back(anim::makeMotionPair(runPair.slow, runPair.fast));
        setup.groupFirst = {0, scenario.characters};
      }
      start = setup.crowd.placement[0];
      scene::Scene scene(test::gpuContext(), std::move(setup), cache, lod);
      runs[prepared] = run(scene, 20, 1.0f / 30.0f, camera, 800, 450,
                           prepared == 1 ? Start::Prepared : Start::Still);
      CHECK(scene.seconds() == doctest::Approx(20.0 / 30.0));
    }
    size_t placementsDiffer = 0, motionsDiffer = 0;
    for (uint32_t i = 0; i < runs[0].placement.size(); ++i) {
      placementsDiffer += runs[1].placement[i] != runs[0].placement[i];
      motionsDiffer += runs[1].motion[i] != runs[0].motion[i];
    }
    CHECK(placementsDiffer == 0);
    CHECK(motionsDiffer == 0);
    CHECK(compareImages(runs[1].image, runs[0].image, 0).maxError == 0);
    CHECK(runs[1].cache.hits == runs[0].cache.hits);
    CHECK(runs[1].cache.misses == runs[0].cache.misses);
    CHECK(runs[1].cache.entries == runs[0].cache.entries);
    // The preparation drew the crowd as it stands before the first step: nearer the first frame
    // (a step later) than the first frame is to the last (19 steps later). A preparation that
    // drew nothing would leave the target as it was made.
    const double preparedToFirst =
        compareImages(runs[1].prepared, runs[1].first, 24).fractionDifferent;
    const double firstToLast = compareImages(runs[1].first, runs[1].image, 24).fractionDifferent;
    MESSAGE("pixels over 24 levels apart: preparation to first frame ", preparedToFirst,
            ", first to last frame ", firstToLast);
    CHECK(preparedToFirst > 0.0);
    CHECK(preparedToFirst < firstToLast);
    // The characters moved: the comparison is between two runs that did something.
    CHECK(glm::length(glm::vec2(runs[0].placement[0].x - start.x,
                                runs[0].placement[0].z - start.z)) > 0.2f);
  }
}

TEST_CASE("scene: a frame of zero seconds moves no one, exactly") {
  // Root motion of a zero step: the difference of two equal roots, which fused multiply-adds
  // would leave a few ulp off zero. Plain root motion (no LOD) and the one that does the
  // coverage, for one clip set and for two (the passes that serve every group at once).
  const anim::ClipPair walk = anim::defaultWalkPair(), runPair = anim::defaultRunPair();
  crowd::ScenarioOptions scenario;
  scenario.characters = 400;
  scenario.seed = 3;
  const render::Camera camera = render::cameraPreset("wide", crowd::scenarioExtent(scenario));
  for (bool lodOn : {false, true})
    for (bool twoSets : {false, true}) {
      CAPTURE(lodOn);
      CAPTURE(twoSets);
      scene::SceneSetup setup;
      setup.crowd = crowd::makeScenario(scenario);
      setup.pairs.push_back(anim::makeMotionPair(runPair.slow, runPair.fast));
      setup.groupFirst = {0, scenario.characters};
      if (twoSets) {
        setup.pairs.push_back(anim::makeMotionPair(walk.slow, walk.fast));
        setup.groupFirst = {0, scenario.characters / 2, scenario.characters};
      }
      const synth::LodOptions lod{lodOn, {}, &runPair.slow.skeleton, 0.0f};
      scene::Scene scene(test::gpuContext(), std::move(setup), {}, lod);
      const Rendered moved = run(scene, 3, 1.0f / 30.0f, camera, 160, 90);
      const Rendered still = run(scene, 1, 0.0f, camera, 160, 90);
      size_t differ = 0;
      for (uint32_t i = 0; i < scene.count(); ++i)
        differ += still.placement[i] != moved.placement[i] || still.motion[i] != moved.motion[i];
      CHECK(differ == 0);
    }
}
