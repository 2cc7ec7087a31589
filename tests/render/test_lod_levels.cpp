// The coverage LOD as drawn: placements are no bones (Bandai Namco's ground-level root), every
// figure at least 40 px tall keeps its four limbs, levels change at most once a second, and
// the far level's silhouette covers the full one's. CPU twins throughout (coverageCpu,
// drawnJointMatrices, splatJointsCpu), which test_joint_splat.cpp and test_coverage.cpp tie to
// the GPU passes.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "anim/bvh.h"
#include "anim/default_clips.h"
#include "anim/pair_placement.h"
#include "anim/reference_synth.h"
#include "core/error.h"
#include "crowd/scenario.h"
#include "render/crowd_renderer.h"
#include "render/joint_lod_cpu.h"
#include "render/joint_splat.h"
#include "render/joint_splat_cpu.h"
#include "synth/cpu_synth.h"
#include "test_support.h"

using namespace throng;

namespace {

constexpr uint32_t kW = 1280, kH = 720;

struct LodBody {
  anim::ClipPair clips;
  anim::MotionPair pair;
  synth::BodyParts parts;
  synth::CoverageParts levels;
  uint64_t bones = 0;
  uint32_t jointCount = 0;
  explicit LodBody(anim::ClipPair c, const synth::CoverageThresholds& thresholds = {})
      : clips(std::move(c)) {
    pair = anim::makeMotionPair(clips.slow, clips.fast);
    parts = synth::describeBodyParts(clips.slow.skeleton);
    synth::setMeanCentres(parts, pair);
    levels = synth::makeCoverageParts(parts, thresholds);
    bones = anim::drawnBoneMask(anim::placementJoints(pair));
    jointCount = uint32_t(pair.jointCount());
  }
};

const LodBody& defaultBody() {
  static LodBody body(anim::defaultRunPair());
  return body;
}

synth::CoverageCamera lodCamera(const render::Camera& camera) {
  return synth::coverageCamera(camera.view(), camera.fovYDegrees, kW, kH, camera.nearPlane);
}

gpu_types::FrameUniforms frameOf(const render::Camera& camera) {
  render::DrawParams params;
  params.camera = camera;
  params.width = kW;
  params.height = kH;
  return render::makeFrameUniforms(params);
}

// A joint's position: the end of its bone (the root's centre).
glm::vec3 jointPoint(const synth::JointPoint& a) {
  return glm::vec3(a.positionRadius);
}

bool isDrawn(const synth::JointMatrix& a) {
  return a.row0 != glm::vec4(0.0f) || a.row1 != glm::vec4(0.0f);
}

// The figure's height on screen in pixels (its joints' vertical extent); 0 when any joint is
// behind the camera or every joint is off screen.
float screenHeight(const gpu_types::FrameUniforms& frame, const synth::JointPoint* joints,
                   uint32_t count) {
  float lo = 1e30f, hi = -1e30f;
  bool onScreen = false;
  for (uint32_t j = 0; j < count; ++j) {
    glm::vec4 clip = frame.viewProjection * glm::vec4(jointPoint(joints[j]), 1.0f);
    if (clip.w <= 0.1f) return 0.0f;
    glm::vec2 pixel = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * glm::vec2(kW, kH);
    onScreen = onScreen || (pixel.x >= 0 && pixel.x < kW && pixel.y >= 0 && pixel.y < kH);
    lo = std::min(lo, pixel.y);
    hi = std::max(hi, pixel.y);
  }
  return onScreen ? hi - lo : 0.0f;
}

std::vector<synth::CoverageMask> levelMasks(const synth::CoverageParts& levels, size_t n,
                                            uint32_t level) {
  const gpu_types::CoverageLevel& l = levels.levels[level];
  return std::vector<synth::CoverageMask>(n, synth::CoverageMask{l.synthLo, l.synthHi, level, 0u});
}

}  // namespace

TEST_CASE("bones: a ground-level root and the segment up to the pelvis are placements, not bones") {
  const LodBody& body = defaultBody();
  CHECK(body.bones == body.parts.allMask);  // the built-in root is the pelvis: every bone drawn
  CHECK(anim::drawnBoneMask(body.clips.slow.skeleton.placementJoints()) == body.parts.allMask);
  if (!test::haveSharedData("bvh/bandai_namco") || !test::haveSharedData("bvh/cmu")) return;
  const auto bandaiDir = test::sharedDataDir() / "bvh/bandai_namco";
  LodBody bandai(anim::loadClipPair(bandaiDir / "dataset-1_run_normal_001.bvh",
                                    bandaiDir / "dataset-1_dash_normal_001.bvh"));
  const anim::Skeleton& skeleton = bandai.clips.slow.skeleton;
  const int root = skeleton.findJoint("joint_Root"), hips = skeleton.findJoint("Hips");
  REQUIRE(root == 0);
  REQUIRE(hips > 0);
  // Decided from the skeleton (rest pose) and from the motion pair alike.
  CHECK(skeleton.placementJoints() == anim::placementJoints(bandai.pair));
  CHECK(anim::drawnBoneMask(skeleton.placementJoints()) ==
        (bandai.parts.allMask & ~(1ull << root) & ~(1ull << hips)));
  anim::Skeleton cmu =
      anim::loadBvh(test::sharedDataDir() / "bvh/cmu/cmu_35_17_runjog.bvh").skeleton;
  CHECK(anim::drawnBoneMask(cmu.placementJoints()) == (uint64_t(1) << cmu.jointCount()) - 1);

  // Drawn ellipsoids over a run cycle: nothing but the legs reaches under 40 cm below the pelvis.
  uint64_t legs = 0;
  for (int k : {3, 4})
    for (int j : bandai.parts.parts[size_t(k)].joints) legs |= uint64_t(1) << j;
  crowd::Crowd crowd;
  crowd.resize(12);
  for (size_t i = 0; i < crowd.size(); ++i) {
    crowd.placement[i] = glm::vec4(3.0f * float(i), 0.0f, 0.0f, 0.5f * float(i));
    crowd.motion[i] = glm::vec4(float(i) / 12.0f, float(i % 2), float(i % 2), 1.0f);
  }
  const uint32_t n = bandai.jointCount;
  std::vector<synth::JointPoint> joints(crowd.size() * n);
  synth::poseCrowdCpu(bandai.pair, crowd, joints, 1);
  std::vector<synth::JointMatrix> drawn =
      render::drawnJointMatrices(joints, bandai.pair.parents, bandai.bones);
  std::vector<synth::JointMatrix> unmasked =
      render::drawnJointMatrices(joints, bandai.pair.parents, ~uint64_t(0));
  auto lowestBelowPelvis = [&](const std::vector<synth::JointMatrix>& matrices) {
    float worst = -1e30f;  // how far the lowest non-leg ellipsoid reaches under pelvis − 0.4 m
    for (size_t c = 0; c < crowd.size(); ++c) {
      const float pelvisY = jointPoint(joints[c * n + uint32_t(hips)]).y;
      for (uint32_t j = 0; j < n; ++j) {
        const synth::JointMatrix& a = matrices[c * n + j];
        if (((legs >> j) & 1u) || !isDrawn(a)) continue;
        // Ellipsoid B·u + c over |u| ≤ 1 (u in the unit sphere of the sprite): its lowest y.
        const glm::vec3 rowY(a.row1.x, 0.5f * a.row1.y, a.row1.z);
        const float bottom = a.row1.w + 0.5f * a.row1.y - glm::length(rowY);
        worst = std::max(worst, (pelvisY - 0.4f) - bottom);
      }
    }
    return worst;
  };
  const float withPlacements = lowestBelowPelvis(unmasked), without = lowestBelowPelvis(drawn);
  MESSAGE("Bandai Namco: non-leg ellipsoids reach ", withPlacements,
          " m under pelvis - 0.4 m when placements are drawn, ", without, " m when they are not");
  CHECK(withPlacements > 0.3f);
  CHECK(without <= 0.0f);
}

TEST_CASE("bones: placements are decided from the geometry and the channels, not from names") {
  // root, pelvis 0.9 m above it, a 5 cm helper beside the root, a spine, two legs down to the
  // floor.
  const std::vector<int32_t> parents = {-1, 0, 0, 1, 1, 4, 1, 6};
  const std::vector<glm::vec3> ground = {{0, 0, 0},         {0, 0.9f, 0},     {0.05f, 0, 0},
                                         {0, 1.4f, 0},      {0.1f, 0.85f, 0}, {0.1f, 0.1f, 0},
                                         {-0.1f, 0.85f, 0}, {-0.1f, 0.1f, 0}};
  std::vector<bool> placement = anim::placementJoints(parents, ground);
  CHECK(placement == std::vector<bool>{true, true, false, false, false, false, false, false});
  // The same body with its root at the pelvis: no placement, unless the root only translates.
  std::vector<glm::vec3> pelvisRoot = ground;
  pelvisRoot[0].y = 0.9f;
  pelvisRoot[2].y = 0.9f;
  CHECK(anim::drawnBoneMask(anim::placementJoints(parents, pelvisRoot)) == 0xFFu);
  std::vector<bool> translationOnly(parents.size(), false);
  translationOnly[0] = true;
  CHECK(anim::drawnBoneMask(anim::placementJoints(parents, pelvisRoot, translationOnly)) == 0xFEu);
  // Too few joints to tell: nothing is a placement.
  const std::vector<int32_t> two = {-1, 0};
  const std::vector<glm::vec3> twoPositions = {{0, 0, 0}, {0, 1, 0}};
  CHECK(anim::drawnBoneMask(anim::placementJoints(two, twoPositions)) == 3u);
}

TEST_CASE(
    "LOD: every figure at least 40 px tall is drawn with four limbs (random crowds, default "
    "cameras)") {
  const LodBody& body = defaultBody();
  const uint32_t n = body.jointCount;
  size_t allTall = 0;
  for (const char* preset : {"wide", "street", "top", "closeup"}) {
    for (uint32_t seed : {1u, 2u}) {
      crowd::ScenarioOptions options;
      options.characters = preset == std::string("wide") ? 3000 : 800;
      options.seed = seed;
      crowd::Crowd crowd = crowd::makeScenario(options);
      const render::Camera camera = render::cameraPreset(preset, crowd::scenarioExtent(options));
      std::vector<synth::CoverageMask> masks(crowd.size());
      synth::coverageCpu(lodCamera(camera), body.levels, n, crowd, {}, masks, {});
      std::vector<synth::JointPoint> joints(crowd.size() * n);
      synth::poseCrowdCpu(body.pair, crowd, joints, 2);
      const std::vector<synth::JointMatrix> drawn =
          render::drawnJointMatrices(joints, body.pair.parents, body.bones, masks, &body.levels);
      const gpu_types::FrameUniforms frame = frameOf(camera);
      size_t tall = 0, missing = 0, levels[3] = {0, 0, 0}, synthesized = 0, sprites = 0;
      for (size_t c = 0; c < crowd.size(); ++c) {
        ++levels[masks[c].level];
        synthesized += size_t(synth::countJoints(synth::maskBits(masks[c])));
        for (uint32_t j = 0; j < n; ++j) sprites += isDrawn(drawn[c * n + j]) ? 1 : 0;
        if (screenHeight(frame, &joints[c * n], n) < 40.0f) continue;
        ++tall;
        for (int k : {0, 1, 3, 4}) {
          const synth::BodyPart& limb = body.parts.parts[size_t(k)];
          if (!isDrawn(drawn[c * n + uint32_t(limb.upper)]) ||
              !isDrawn(drawn[c * n + uint32_t(limb.lower)])) {
            ++missing;
            MESSAGE("character ", c, " level ", masks[c].level, " state ", masks[c].state,
                    " height ", screenHeight(frame, &joints[c * n], n), " limb ", k);
          }
        }
      }
      MESSAGE(std::string(preset), " camera, seed ", seed, ", ", crowd.size(),
              " characters: far/mid/near ", levels[0], "/", levels[1], "/", levels[2],
              "; joints synthesized ", double(synthesized) / double(crowd.size()), " and drawn ",
              double(sprites) / double(crowd.size()), " per character; ", tall,
              " at least 40 px tall, limbs missing ", missing);
      CHECK(missing == 0);
      allTall += tall;
    }
  }
  CHECK(allTall > 500);
}

namespace {

struct LevelChanges {
  size_t changes = 0;
  double perCharacterSecond = 0.0;
  double shortestGap = 1e9;  // seconds between two changes of one character
  size_t mostInOneFrame = 0;
};

// Steps the crowd (CPU root motion) for `frames` frames of dt seconds under cameraAt(t in [0, 1))
// and counts the level changes after the first frame (which sets every level).
template <typename CameraAt>
LevelChanges countLevelChanges(const LodBody& body, const synth::CoverageParts& levels,
                               crowd::Crowd crowd, CameraAt cameraAt, int frames, float dt) {
  LevelChanges out;
  std::vector<synth::CoverageMask> masks(crowd.size());
  std::vector<int> lastChange(crowd.size(), -1);
  for (int f = 0; f < frames; ++f) {
    for (size_t i = 0; i < crowd.size(); ++i)
      anim::stepCharacter(body.pair, crowd.placement[i], crowd.motion[i], dt, crowd.steering);
    std::vector<synth::CoverageMask> before = masks;
    synth::coverageCpu(lodCamera(cameraAt(float(f) / float(frames))), levels, body.jointCount,
                       crowd, {}, masks, {});
    if (f == 0) continue;
    size_t thisFrame = 0;
    for (size_t i = 0; i < masks.size(); ++i) {
      if (masks[i].level == before[i].level) continue;
      ++thisFrame;
      if (lastChange[i] >= 0)
        out.shortestGap = std::min(out.shortestGap, double(f - lastChange[i]) * dt);
      lastChange[i] = f;
    }
    out.changes += thisFrame;
    out.mostInOneFrame = std::max(out.mostInOneFrame, thisFrame);
  }
  out.perCharacterSecond = double(out.changes) / double(crowd.size()) / (double(frames) * dt);
  return out;
}

std::string describe(const LevelChanges& c) {
  return concat(c.changes, " changes, ", c.perCharacterSecond,
                " per character per second, at most ", c.mostInOneFrame,
                " in a frame, shortest gap ", c.shortestGap, " s");
}

}  // namespace

TEST_CASE(
    "LOD: a character changes level at most once a second (moving crowds, still and dollying "
    "cameras)") {
  const LodBody& body = defaultBody();
  synth::CoverageThresholds instantThresholds;
  instantThresholds.hysteresis = 0.0f;
  instantThresholds.minChangeSeconds = 0.0f;
  const LodBody instant(anim::defaultRunPair(), instantThresholds);
  const float dt = 1.0f / 30.0f;

  // 800 characters, the wide camera moving in to a fifth of its distance and back out in 20 s.
  crowd::ScenarioOptions options;
  options.characters = 800;
  options.seed = 4;
  const crowd::Crowd crowd = crowd::makeScenario(options);
  const render::Camera wide = render::cameraPreset("wide", crowd::scenarioExtent(options));
  auto dolly = [&](float t) {
    render::Camera camera = wide;
    camera.eye =
        glm::mix(wide.eye, glm::mix(wide.target, wide.eye, 0.2f), 1.0f - std::abs(2.0f * t - 1.0f));
    return camera;
  };
  const LevelChanges moving = countLevelChanges(body, body.levels, crowd, dolly, 600, dt);
  const LevelChanges movingInstant = countLevelChanges(body, instant.levels, crowd, dolly, 600, dt);
  MESSAGE("dollying, 800 characters, 20 s: ", describe(moving),
          "; without hysteresis and cycle ends ", describe(movingInstant));
  CHECK(moving.changes > 200);
  CHECK(moving.shortestGap >= 1.0);
  CHECK(movingInstant.shortestGap < 1.0);  // the scenario does provoke quick changes

  // The street scene: 60 characters at 0.05 per m², the street camera still, 10 s.
  crowd::ScenarioOptions sparse;
  sparse.characters = 60;
  sparse.density = 0.05f;
  const crowd::Crowd street = crowd::makeScenario(sparse);
  const render::Camera still = render::cameraPreset("street", crowd::scenarioExtent(sparse));
  auto fixed = [&](float) { return still; };
  const LevelChanges walking = countLevelChanges(body, body.levels, street, fixed, 300, dt);
  const LevelChanges walkingInstant =
      countLevelChanges(body, instant.levels, street, fixed, 300, dt);
  MESSAGE("street camera, 60 characters, 10 s: ", describe(walking),
          "; without hysteresis and cycle ends ", describe(walkingInstant));
  CHECK(walking.shortestGap >= 1.0);
}

TEST_CASE("LOD: the far and mid levels' silhouettes cover the full level's pixels") {
  const LodBody& body = defaultBody();
  const uint32_t n = body.jointCount;
  render::Camera camera;
  camera.target = glm::vec3(0.0f, 0.8f, 0.0f);
  for (auto [level, tallPx] :
       {std::pair<uint32_t, float>{gpu_types::kLevelFar, 50.0f}, {gpu_types::kLevelMid, 100.0f}}) {
    const float distance = 869.12f * body.parts.height / tallPx;
    camera.eye = glm::vec3(0.0f, 1.6f, -distance);
    const gpu_types::FrameUniforms frame = frameOf(camera);
    crowd::Crowd crowd;
    crowd.resize(24);
    for (size_t i = 0; i < crowd.size(); ++i) {
      crowd.placement[i] = glm::vec4(0.0f, 0.0f, 0.0f, 0.8f * float(i % 8));
      crowd.motion[i] = glm::vec4(float(i) / 24.0f, float(i % 3) / 2.0f, 0.0f, 1.0f);
    }
    std::vector<synth::JointPoint> joints(crowd.size() * n);
    synth::poseCrowdCpu(body.pair, crowd, joints, 2);
    size_t full = 0, covered = 0, baseCovered = 0;
    double worst = 1.0;
    // For comparison: the base joints alone (pelvis and lower spine, what off-screen
    // characters synthesize and what a far character was drawn with before it kept its limbs).
    const synth::CoverageMask baseOnly{uint32_t(body.parts.baseMask),
                                       uint32_t(body.parts.baseMask >> 32), gpu_types::kLevelNear,
                                       0u};
    for (size_t c = 0; c < crowd.size(); ++c) {
      std::span<const synth::JointPoint> one(&joints[c * n], n);
      auto fullLevel = render::drawnJointMatrices(one, body.pair.parents, body.bones,
                                                  levelMasks(body.levels, 1, gpu_types::kLevelNear),
                                                  &body.levels);
      auto lower = render::drawnJointMatrices(one, body.pair.parents, body.bones,
                                              levelMasks(body.levels, 1, level), &body.levels);
      auto a = render::splatJointsCpu(fullLevel, frame, n, 1e9f, kW, kH).visibility;
      auto b = render::splatJointsCpu(lower, frame, n, 1e9f, kW, kH).visibility;
      auto base =
          render::splatJointsCpu(render::drawnJointMatrices(one, body.pair.parents, body.bones,
                                                            std::span(&baseOnly, 1), &body.levels),
                                 frame, n, 1e9f, kW, kH)
              .visibility;
      size_t f = 0, both = 0;
      for (size_t p = 0; p < a.size(); ++p) {
        f += a[p] != render::kEmptyPixel;
        both += a[p] != render::kEmptyPixel && b[p] != render::kEmptyPixel;
        baseCovered += a[p] != render::kEmptyPixel && base[p] != render::kEmptyPixel;
      }
      full += f;
      covered += both;
      worst = std::min(worst, double(both) / double(std::max<size_t>(f, 1)));
    }
    const double share = double(covered) / double(std::max<size_t>(full, 1));
    MESSAGE((level == gpu_types::kLevelFar ? "far" : "mid"), " level at ", tallPx,
            " px tall: covers ", 100.0 * share, "% of the full level's ", full,
            " pixels over 24 poses (worst pose ", 100.0 * worst, "%); the base joints alone cover ",
            100.0 * double(baseCovered) / double(std::max<size_t>(full, 1)), "%");
    CHECK(full > 24 * 100);
    CHECK(share >= 0.8);
  }
}

TEST_CASE("LOD: the bench's overhead camera puts about a tenth of a random crowd on screen") {
  CHECK_THROWS_AS(render::overheadCamera(0.0f, 0.1f, 1.0f), Error);
  CHECK_THROWS_AS(render::overheadCamera(10.0f, 0.0f, 1.0f), Error);
  const LodBody& body = defaultBody();
  crowd::ScenarioOptions options;
  options.characters = 20000;
  crowd::Crowd crowd = crowd::makeScenario(options);
  const render::Camera camera =
      render::overheadCamera(crowd::scenarioExtent(options), 0.1f, 1280.0f / 720.0f);
  std::vector<synth::CoverageMask> masks(crowd.size());
  synth::coverageCpu(lodCamera(camera), body.levels, body.jointCount, crowd, {}, masks, {});
  const auto onScreen = std::count_if(
      masks.begin(), masks.end(), [](const synth::CoverageMask& m) { return (m.lo | m.hi) != 0u; });
  MESSAGE(onScreen, " of ", crowd.size(), " characters on screen");
  // A tenth of the ground, and the characters standing at its border whose bodies reach in.
  CHECK(onScreen > 1700);
  CHECK(onScreen < 2600);
}
