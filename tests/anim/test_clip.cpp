// toClip: quaternions per joint per frame, the root's position and the other joints'
// per-frame translations.
#include <algorithm>

#include <doctest/doctest.h>
#include <glm/gtc/quaternion.hpp>

#include "anim/bvh.h"
#include "anim/clip.h"
#include "anim/euler.h"
#include "core/error.h"
#include "core/math.h"
#include "test_support.h"

using namespace throng::anim;

namespace {

// Root with 6 channels (Z X Y), a 6-channel child (Bandai style) and a 3-channel leaf.
constexpr const char* kSmall = R"(HIERARCHY
ROOT Hips
{
  OFFSET 1 2 3
  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
  JOINT Spine
  {
    OFFSET 0 10 0
    CHANNELS 6 Xposition Yposition Zposition Xrotation Yrotation Zrotation
    JOINT Head
    {
      OFFSET 0 5 0
      CHANNELS 3 Yrotation Zrotation Xrotation
      End Site
      {
        OFFSET 0 3 0
      }
    }
  }
}
MOTION
Frames: 2
Frame Time: 0.04
10 20 30 90 0 0 7 8 9 0 90 0 0 0 0
-1 -2 -3 0 0 0 0 0 0 45 0 0 0 90 -30
)";

bool near(glm::vec4 a, glm::vec4 b) { return glm::length(a - b) < 1e-5f || glm::length(a + b) < 1e-5f; }

}  // namespace

TEST_CASE("toClip converts every joint's channels in its own order") {
  Clip clip = toClip(parseBvh(kSmall, "small.bvh"));
  CHECK(clip.name == "small");
  REQUIRE(clip.jointCount() == 3);
  REQUIRE(clip.frameCount == 2);
  CHECK(clip.frameTime == doctest::Approx(0.04f));
  REQUIRE(clip.rotations.size() == 6);
  REQUIRE(clip.rootPositions.size() == 2);
  CHECK(clip.cycleTravel == glm::vec3(0.0f));

  const float s = std::sqrt(0.5f);
  CHECK(near(clip.rotation(0, 0), {0, 0, s, s}));  // root: Zrotation 90
  CHECK(near(clip.rotation(0, 1), {0, s, 0, s}));  // spine: Yrotation 90 (X Y Z order)
  CHECK(near(clip.rotation(0, 2), {0, 0, 0, 1}));
  CHECK(near(clip.rotation(1, 0), {0, 0, 0, 1}));
  CHECK(near(clip.rotation(1, 1), {std::sin(throng::kPi / 8), 0, 0, std::cos(throng::kPi / 8)}));
  // Head, Y Z X order with Y = 0, Z = 90, X = -30: R = Rz(90) * Rx(-30).
  glm::vec4 expected = throng::quatMul(axisRotation(Channel::Zrotation, 90.0f),
                                       axisRotation(Channel::Xrotation, -30.0f));
  CHECK(near(clip.rotation(1, 2), expected));
  for (const glm::vec4& q : clip.rotations) CHECK(glm::length(q) == doctest::Approx(1.0f));
}

TEST_CASE("root position is its offset plus the channels; other joints' channels replace") {
  Clip clip = toClip(parseBvh(kSmall, "small.bvh"));
  CHECK(clip.rootPositions[0] == glm::vec3(11, 22, 33));
  CHECK(clip.rootPositions[1] == glm::vec3(0, 0, 0));
  // The spine's position channels (7 8 9, then 0 0 0) are its translation at that frame;
  // the head has none and keeps its OFFSET. The skeleton keeps the rest offsets.
  REQUIRE(clip.animatedOffsets.size() == 6);
  CHECK(clip.offset(0, 1) == glm::vec3(7, 8, 9));
  CHECK(clip.offset(1, 1) == glm::vec3(0, 0, 0));
  CHECK(clip.offset(0, 2) == glm::vec3(0, 5, 0));
  CHECK(clip.offset(1, 2) == glm::vec3(0, 5, 0));
  CHECK(clip.offset(0, 0) == clip.rootPositions[0]);  // the root: its global position
  CHECK(clip.offset(1, 0) == clip.rootPositions[1]);
  CHECK(clip.skeleton.joints[1].offset == glm::vec3(0, 10, 0));
}

TEST_CASE("a joint's single position channel replaces only the component it names") {
  // BVH files give a joint 3 rotations or all 6 channels; a RawClip built in code may name
  // fewer, and toClip keeps the OFFSET's other components.
  RawClip raw;
  raw.sourceName = "hips";
  raw.skeleton.joints.push_back(Joint{"Root", -1, {0, 0, 0}, {Channel::Xposition}, std::nullopt});
  raw.skeleton.joints.push_back(
      Joint{"Hips", 0, {1, 90, 2}, {Channel::Zrotation, Channel::Yposition}, std::nullopt});
  raw.frameCount = 2;
  raw.frameTime = 0.1f;
  raw.channelCount = 3;
  raw.values = {0, 0, 85, 5, 90, 88};
  Clip clip = toClip(raw);
  CHECK(clip.offset(0, 1) == glm::vec3(1, 85, 2));
  CHECK(clip.offset(1, 1) == glm::vec3(1, 88, 2));
  CHECK(clip.rootPositions[1] == glm::vec3(5, 0, 0));
  CHECK(near(clip.rotation(1, 1), axisRotation(Channel::Zrotation, 90.0f)));
}

TEST_CASE("a root without position channels stays at its offset") {
  std::string text = R"(HIERARCHY
ROOT Hips
{
  OFFSET 4 5 6
  CHANNELS 3 Zrotation Yrotation Xrotation
}
MOTION
Frames: 3
Frame Time: 0.5
0 0 0
10 0 0
20 0 0
)";
  Clip clip = toClip(parseBvh(text, "rooted.bvh"));
  REQUIRE(clip.rootPositions.size() == 3);
  for (const glm::vec3& p : clip.rootPositions) CHECK(p == glm::vec3(4, 5, 6));
  CHECK(clip.animatedOffsets.empty());
  CHECK(clip.rotation(2, 0).z == doctest::Approx(std::sin(glm::radians(10.0f))));
}

TEST_CASE("toClip rejects an inconsistent RawClip instead of reading past its values") {
  RawClip raw = parseBvh(kSmall, "small.bvh");
  RawClip shortValues = raw;
  shortValues.values.pop_back();
  CHECK_THROWS_AS(toClip(shortValues), throng::Error);
  RawClip badParent = raw;
  badParent.skeleton.joints[1].parent = 2;
  CHECK_THROWS_AS(toClip(badParent), throng::Error);
  RawClip empty;
  CHECK_THROWS_AS(toClip(empty), throng::Error);
}

TEST_CASE("toClip on real captures: T-pose frame is identity and the root travels") {
  if (!throng::test::haveSharedData("bvh/cmu/cmu_09_01_run.bvh")) return;
  Clip clip = toClip(loadBvh(throng::test::sharedDataDir() / "bvh/cmu/cmu_09_01_run.bvh"));
  REQUIRE(clip.frameCount == 149);
  // Frame 0 of a CMU capture is a T-pose written as integers; LHipJoint (joint 1) is 0 0 0.
  CHECK(near(clip.rotation(0, 1), {0, 0, 0, 1}));
  CHECK(clip.rootPositions[0].x == doctest::Approx(-0.3071f));
  CHECK(clip.rootPositions[0].y == doctest::Approx(17.6356f));
  CHECK(clip.rootPositions[0].z == doctest::Approx(-28.2214f));
  // A run along +z: about 3.5 m/s over 1.2 s at ~0.0564 m/unit is tens of units.
  float travel = clip.rootPositions.back().z - clip.rootPositions[1].z;
  CHECK(std::abs(travel) > 30.0f);
  CHECK(clip.animatedOffsets.empty());  // only the root has position channels
}

TEST_CASE("toClip on Bandai Namco: the hips carry the height and sway, the root slides") {
  struct Case {
    const char* file;
    float low, high;  // the hips' Yposition over the file, centimetres
  };
  for (Case c : {Case{"bvh/bandai_namco/dataset-1_run_normal_001.bvh", 84.659f, 94.2034f},
                 Case{"bvh/bandai_namco/dataset-1_dash_normal_001.bvh", 82.5403f, 89.7401f}}) {
    if (!throng::test::haveSharedData(c.file)) return;
    Clip clip = toClip(loadBvh(throng::test::sharedDataDir() / c.file));
    CAPTURE(c.file);
    const int hips = clip.skeleton.findJoint("Hips");
    const int spine = clip.skeleton.findJoint("Spine");
    REQUIRE(hips == 1);
    REQUIRE(spine > hips);
    REQUIRE(clip.animatedOffsets.size() == clip.rotations.size());
    float low = 1e9f, high = -1e9f;
    for (int f = 0; f < clip.frameCount; ++f) {
      CHECK(clip.rootPositions[size_t(f)].y == 0.0f);  // the root only slides
      low = std::min(low, clip.offset(f, hips).y);
      high = std::max(high, clip.offset(f, hips).y);
      // The other bones write their OFFSET again every frame.
      glm::vec3 rest = clip.skeleton.joints[size_t(spine)].offset;
      CHECK(glm::length(clip.offset(f, spine) - rest) < 1e-4f);
    }
    CHECK(low == doctest::Approx(c.low));
    CHECK(high == doctest::Approx(c.high));
    // The rest OFFSET (93.99) is the T-pose height, above most of the motion.
    CHECK(clip.skeleton.joints[size_t(hips)].offset.y == doctest::Approx(93.9915f));
  }
  if (!throng::test::haveSharedData("bvh/bandai_namco/dataset-1_run_normal_001.bvh")) return;
  Clip run = toClip(
      loadBvh(throng::test::sharedDataDir() / "bvh/bandai_namco/dataset-1_run_normal_001.bvh"));
  CHECK(run.offset(0, 1) == glm::vec3(-0.454435f, 86.083f, 8.33909e-14f));
  CHECK(run.offset(3, 1).y == doctest::Approx(92.1612f));
}
