#include <doctest/doctest.h>

#include "anim/bvh.h"
#include "anim/clip_prep.h"
#include "anim/default_clips.h"
#include "anim/gait.h"
#include "core/error.h"
#include "synth/body_parts.h"
#include "synth/coverage.h"
#include "test_support.h"

using namespace throng;

namespace {

int jointIndex(const anim::Skeleton& s, const std::string& name) {
  int j = s.findJoint(name);
  REQUIRE_MESSAGE(j >= 0, name);
  return j;
}

std::string describe(const anim::Skeleton& s, const synth::BodyParts& parts) {
  std::string text = parts.method + ":";
  for (int k = 0; k < synth::kBodyPartCount; ++k) {
    const synth::BodyPart& p = parts.parts[size_t(k)];
    text += concat(" ", synth::bodyPartName(k), "=", s.joints[size_t(p.centreJoint)].name, " r=", p.radius, " +",
                   synth::countJoints(p.activates), ";");
  }
  return text + concat(" base ", synth::countJoints(parts.baseMask), " of ", parts.jointCount);
}

void checkClosedMasks(const anim::Skeleton& s, const synth::BodyParts& parts) {
  std::vector<int32_t> parents = s.parents();
  CHECK(synth::parentsBeforeChildren(parts.baseMask, parents));
  uint64_t all = parts.baseMask;
  for (const synth::BodyPart& p : parts.parts) {
    CHECK((p.activates & parts.baseMask) == 0);
    CHECK(synth::parentsBeforeChildren(p.activates | parts.baseMask, parents));
    all |= p.activates;
  }
  CHECK(all == parts.allMask);
}

}  // namespace

TEST_CASE("body parts of the built-in 25-joint skeleton, found from the joint names") {
  anim::Skeleton s = anim::gaitSkeleton();
  synth::BodyParts parts = synth::describeBodyParts(s);
  MESSAGE(describe(s, parts));
  CHECK(parts.method == "names");
  CHECK(parts.parts[0].centreJoint == jointIndex(s, "LeftForeArm"));
  CHECK(parts.parts[1].centreJoint == jointIndex(s, "RightForeArm"));
  CHECK(parts.parts[2].centreJoint == jointIndex(s, "Spine2"));
  CHECK(parts.parts[3].centreJoint == jointIndex(s, "LeftLeg"));
  CHECK(parts.parts[4].centreJoint == jointIndex(s, "RightLeg"));
  // The paper's levels: far = base (4 joints), mid = + upper torso and head (7), near = 25.
  CHECK(synth::countJoints(parts.baseMask) == 4);
  CHECK(synth::countJoints(parts.baseMask | parts.parts[2].activates) == 7);
  CHECK(synth::countJoints(parts.allMask) == 25);
  CHECK(synth::countJoints(parts.parts[0].activates) == 6);  // the arm and the chest it hangs from
  CHECK(synth::countJoints(parts.parts[3].activates) == 4);
  // Bone-path radii: torso Spine2→Hips 0.34 m; arm elbow→clavicle 0.30 + 0.161 m; leg knee→toe.
  CHECK(parts.parts[2].radius == doctest::Approx(0.34f).epsilon(1e-3));
  CHECK(parts.parts[0].radius == doctest::Approx(0.30f + std::sqrt(0.16f * 0.16f + 0.01f * 0.01f)).epsilon(1e-3));
  CHECK(parts.parts[3].radius == doctest::Approx(0.41f + std::sqrt(0.05f * 0.05f + 0.13f * 0.13f)).epsilon(1e-3));
  checkClosedMasks(s, parts);
}

TEST_CASE("body parts: the geometric fallback finds the same parts when names say nothing") {
  anim::Skeleton named = anim::gaitSkeleton();
  anim::Skeleton anonymous = named;
  for (size_t j = 0; j < anonymous.joints.size(); ++j) anonymous.joints[j].name = concat("j", j);
  synth::BodyParts a = synth::describeBodyParts(named);
  synth::BodyParts b = synth::describeBodyParts(anonymous);
  CHECK(b.method == "geometry");
  for (int k = 0; k < synth::kBodyPartCount; ++k) {
    CHECK(a.parts[size_t(k)].centreJoint == b.parts[size_t(k)].centreJoint);
    CHECK(a.parts[size_t(k)].activates == b.parts[size_t(k)].activates);
    CHECK(a.parts[size_t(k)].radius == b.parts[size_t(k)].radius);
  }
  CHECK(a.baseMask == b.baseMask);
}

TEST_CASE("body parts: mean centres follow the motion (knees below the hips, elbows beside the chest)") {
  anim::ClipPair clips = anim::defaultRunPair();
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  synth::BodyParts parts = synth::describeBodyParts(clips.slow.skeleton);
  synth::setMeanCentres(parts, pair);
  const glm::vec3 spine = parts.parts[2].meanCentre;
  MESSAGE("mean centres: left elbow ", parts.parts[0].meanCentre.x, ",", parts.parts[0].meanCentre.y,
          "; mid-spine ", spine.y, "; left knee ", parts.parts[3].meanCentre.y);
  CHECK(spine.y > 0.9f);
  CHECK(spine.y < 1.4f);
  CHECK(parts.parts[3].meanCentre.y < spine.y - 0.5f);
  CHECK(parts.parts[0].meanCentre.x > 0.1f);   // the left side is +x
  CHECK(parts.parts[1].meanCentre.x < -0.1f);
  anim::MotionPair other = pair;
  other.slow.jointCount = 3;
  CHECK_THROWS_WITH_AS(synth::setMeanCentres(parts, other), doctest::Contains("3 joints"), Error);
}

TEST_CASE("body parts of the real captures' skeletons (CMU 31 joints, Bandai Namco 22 joints)") {
  if (!test::haveSharedData("bvh/cmu") || !test::haveSharedData("bvh/bandai_namco")) return;
  anim::Skeleton cmu = anim::loadBvh(test::sharedDataDir() / "bvh/cmu/cmu_35_17_runjog.bvh").skeleton;
  synth::BodyParts c = synth::describeBodyParts(cmu);
  MESSAGE("CMU (radii in file units, ", anim::detectUnits(cmu).metresPerUnit, " m each) ", describe(cmu, c));
  CHECK(c.method == "names");
  CHECK(c.parts[0].centreJoint == jointIndex(cmu, "LeftForeArm"));
  CHECK(c.parts[4].centreJoint == jointIndex(cmu, "RightLeg"));
  CHECK(synth::countJoints(c.allMask) == 31);
  CHECK(synth::countJoints(c.baseMask) < 5);
  checkClosedMasks(cmu, c);

  anim::Skeleton bandai = anim::loadBvh(test::sharedDataDir() / "bvh/bandai_namco/dataset-1_run_normal_001.bvh").skeleton;
  synth::BodyParts b = synth::describeBodyParts(bandai);
  MESSAGE("Bandai Namco (radii in file units, ", anim::detectUnits(bandai).metresPerUnit, " m each) ", describe(bandai, b));
  // The torso's sphere is measured from the pelvis up, not from the ground-level root.
  CHECK(b.parts[2].radius < b.parts[3].radius);
  CHECK(b.method == "names");
  CHECK(b.parts[0].centreJoint == jointIndex(bandai, "LowerArm_L"));
  CHECK(b.parts[1].centreJoint == jointIndex(bandai, "LowerArm_R"));
  CHECK(b.parts[3].centreJoint == jointIndex(bandai, "LowerLeg_L"));
  CHECK(b.parts[4].centreJoint == jointIndex(bandai, "LowerLeg_R"));
  CHECK(((b.baseMask >> jointIndex(bandai, "Hips")) & 1u) == 1u);
  checkClosedMasks(bandai, b);
}

TEST_CASE("body parts: skeletons that cannot be described are reported") {
  anim::Skeleton chain;
  for (int j = 0; j < 3; ++j) chain.joints.push_back({concat("bone", j), j - 1, glm::vec3(0.0f, 0.2f, 0.0f), {}, {}});
  CHECK_THROWS_WITH_AS(synth::describeBodyParts(chain), doctest::Contains("cannot find two arms and two legs in a 3-joint"),
                       Error);
  anim::Skeleton huge = anim::gaitSkeleton();
  while (huge.jointCount() <= 64) huge.joints.push_back({"Extra", 6, glm::vec3(0.0f, 0.05f, 0.0f), {}, {}});
  CHECK_THROWS_WITH_AS(synth::describeBodyParts(huge), doctest::Contains("1..64 joints, the skeleton has 65"), Error);
  anim::Skeleton unordered = anim::gaitSkeleton();
  unordered.joints[3].parent = 7;
  CHECK_THROWS_WITH_AS(synth::describeBodyParts(unordered), doctest::Contains("joint 3 ('Spine2') has parent 7"), Error);
}
