// The CPU reference synthesizer against docs/design.md: slerp properties, w = 0/1 reproduce the
// clips, root motion (eq. 10), heading about +y, and no foot skate on the built-in run.
#include <doctest/doctest.h>

#include <cmath>

#include "anim/default_clips.h"
#include "anim/reference_synth.h"
#include "core/math.h"
#include "core/rng.h"
#include "synth_fixtures.h"

using namespace throng;

namespace {
float quatDistance(glm::vec4 a, glm::vec4 b) {
  return std::min(glm::length(a - b), glm::length(a + b));
}
}  // namespace

TEST_CASE("series slerp stays within 1e-5 of true slerp and keeps slerp's properties") {
  Rng rng(3);
  float worst = 0.0f;
  for (int i = 0; i < 20000; ++i) {
    glm::vec4 a = glm::normalize(
        glm::vec4(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
    glm::vec4 b = glm::normalize(
        glm::vec4(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
    float t = rng.uniform();
    worst = std::max(worst, glm::length(slerpFast(a, b, t) - slerpShortest(a, b, t)));
    REQUIRE(quatDistance(slerpFast(a, b, 0.0f), a) < 1e-6f);
    REQUIRE(quatDistance(slerpFast(a, b, 1.0f), b) < 2e-6f);
    REQUIRE(std::abs(glm::length(slerpFast(a, b, t)) - 1.0f) < 2e-6f);
  }
  MESSAGE("max |slerpFast - slerp| over 20000 random pairs: ", worst);
  CHECK(worst <= 1e-5f);
  // Shortest arc: q and -q are the same rotation; the midpoint must not pass through the far side.
  glm::vec4 a(0, 0, 0, 1), b = -glm::normalize(glm::vec4(0, std::sin(0.2f), 0, std::cos(0.2f)));
  glm::vec4 mid = slerpFast(a, b, 0.5f);
  CHECK(quatDistance(mid, glm::normalize(glm::vec4(0, std::sin(0.1f), 0, std::cos(0.1f)))) < 1e-5f);
  // Constant angular speed: the angle to a grows linearly with t.
  glm::vec4 c = glm::normalize(glm::vec4(std::sin(1.0f), 0, 0, std::cos(1.0f)));
  for (float t : {0.25f, 0.5f, 0.75f})
    CHECK(2.0f * std::acos(slerpFast(glm::vec4(0, 0, 0, 1), c, t).w) ==
          doctest::Approx(2.0f * t).epsilon(1e-4));
}

namespace {
// Joint j's local rotation recovered from a character-space pose.
glm::vec4 localRotation(const anim::MotionPair& pair, const std::vector<anim::PoseJoint>& pose,
                        int j) {
  int p = pair.parents[size_t(j)];
  if (p < 0) return pose[size_t(j)].rotation;
  glm::vec4 parent = pose[size_t(p)].rotation;
  return quatMul(glm::vec4(-glm::vec3(parent), parent.w), pose[size_t(j)].rotation);
}
}  // namespace

TEST_CASE("w = 0 and w = 1 reproduce the slow and fast clips: their rows, and slerp between rows") {
  anim::MotionPair pair = test::syntheticPair(10, 20, 16, 9);
  std::vector<anim::PoseJoint> pose(10);
  for (float w : {0.0f, 1.0f}) {
    const anim::MotionTexture& clip = w == 0.0f ? pair.slow : pair.fast;
    const int frames = clip.frameCount;
    for (int f : {0, 5, 13, frames - 1}) {
      CAPTURE(w);
      CAPTURE(f);
      // On a row the pose is that row; half way to the next (row 0 after the last: the clip is
      // a cycle) it is the slerp of the two.
      anim::poseCharacterSpace(pair, float(f) / float(frames), w, pose);
      for (int j = 0; j < 10; ++j)
        REQUIRE(quatDistance(localRotation(pair, pose, j), clip.rotation(f, j)) < 1e-5f);
      // A phase a hair off the row (f / F in float) is on it: the root is that row bit for bit.
      anim::poseCharacterSpace(pair, float(f) / float(frames) + 1e-6f, w, pose);
      REQUIRE(pose[0].rotation == clip.rotation(f, 0));
      REQUIRE(pose[0].position.y == clip.offset(f, 0).y);
      anim::poseCharacterSpace(pair, (float(f) + 0.5f) / float(frames), w, pose);
      const int next = (f + 1) % frames;
      for (int j = 0; j < 10; ++j) {
        glm::vec4 half = slerpShortest(clip.rotation(f, j), clip.rotation(next, j), 0.5f);
        REQUIRE(quatDistance(localRotation(pair, pose, j), half) < 2e-5f);
      }
    }
  }
}

TEST_CASE("root motion: one cycle travels the blended distance along the heading") {
  anim::ClipPair clips = anim::defaultRunPair();
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  for (float w : {0.0f, 0.3f, 1.0f}) {
    for (float heading : {0.0f, 1.0f, -2.5f}) {
      glm::vec4 placement(0.0f, 0.0f, 0.0f, heading), motion(0.0f, w, w, 1.0f);
      float duration = pair.slow.duration() * (1 - w) + pair.fast.duration() * w;
      // A hair over one cycle, so float rounding cannot leave the phase just short of the wrap.
      int steps = 60;
      for (int s = 0; s < steps; ++s)
        anim::stepCharacter(pair, placement, motion, 1.0001f * duration / steps,
                            anim::Steering::KeepHeading);
      glm::vec3 travel = pair.slow.cycleTravel * (1 - w) + pair.fast.cycleTravel * w;
      glm::vec2 expected(travel.z * std::sin(heading), travel.z * std::cos(heading));
      CHECK(placement.x == doctest::Approx(expected.x).epsilon(0.02).scale(1.0));
      CHECK(placement.z == doctest::Approx(expected.y).epsilon(0.02).scale(1.0));
      CHECK(motion.x < 1e-3f);
    }
  }
}

TEST_CASE("root motion: a step of no time moves no one, exactly") {
  anim::ClipPair clips = anim::defaultRunPair();
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  for (float phase : {0.0f, 0.137f, 0.5f, 0.999f})
    for (float w : {0.0f, 0.43f, 1.0f}) {
      CAPTURE(phase);
      CAPTURE(w);
      const glm::vec4 placement0(3.7f, 0.0f, -12.25f, 0.8f), motion0(phase, w, 0.9f, 1.1f);
      glm::vec4 placement = placement0, motion = motion0;
      anim::stepCharacter(pair, placement, motion, 0.0f, anim::Steering::KeepHeading);
      CHECK(placement == placement0);
      CHECK(motion == motion0);
    }
}

TEST_CASE("root motion: the speed weight changes only at the end of a cycle") {
  anim::MotionPair pair = test::syntheticPair(5, 30, 24, 2);
  glm::vec4 placement(0.0f), motion(0.1f, 0.2f, 0.9f, 1.0f);
  float dt = pair.slow.duration() / 40.0f;
  bool wrapped = false;
  for (int s = 0; s < 60 && !wrapped; ++s) {
    float before = motion.x;
    anim::stepCharacter(pair, placement, motion, dt, anim::Steering::KeepHeading);
    wrapped = motion.x < before;
    CHECK(motion.y == (wrapped ? 0.9f : 0.2f));
  }
  CHECK(wrapped);
}

TEST_CASE("root motion: scale multiplies the displacement; circle steering keeps the radius") {
  anim::ClipPair clips = anim::defaultRunPair();
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  glm::vec4 small(0, 0, 0, 0), large(0, 0, 0, 0), ms(0, 0.5f, 0.5f, 1.0f), ml(0, 0.5f, 0.5f, 1.2f);
  for (int s = 0; s < 30; ++s) {
    anim::stepCharacter(pair, small, ms, 1 / 30.0f, anim::Steering::KeepHeading);
    anim::stepCharacter(pair, large, ml, 1 / 30.0f, anim::Steering::KeepHeading);
  }
  CHECK(large.z == doctest::Approx(1.2f * small.z).epsilon(1e-4));
  glm::vec4 runner(20.0f, 0, 0, 0), m(0, 1.0f, 1.0f, 1.0f);
  for (int s = 0; s < 600; ++s)
    anim::stepCharacter(pair, runner, m, 1 / 30.0f, anim::Steering::Circle);
  CHECK(std::hypot(runner.x, runner.z) == doctest::Approx(20.0f).epsilon(0.03));
}

TEST_CASE("no foot skate: with w fixed the planted foot stays put (built-in run)") {
  anim::ClipPair clips = anim::defaultRunPair();
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  const int toe = clips.slow.skeleton.findJoint("LeftToeBase");
  REQUIRE(toe > 0);
  for (float w : {0.0f, 0.5f, 1.0f}) {
    glm::vec4 placement(0, 0, 0, 0.7f), motion(0, w, w, 1.0f);
    std::vector<anim::PoseJoint> pose(pair.jointCount());
    std::vector<glm::vec3> toeWorld;
    const int frames = pair.slow.frameCount;
    float dt = (pair.slow.duration() * (1 - w) + pair.fast.duration() * w) / frames;
    for (int s = 0; s < 2 * frames; ++s) {
      anim::stepCharacter(pair, placement, motion, dt, anim::Steering::KeepHeading);
      anim::poseCharacterSpace(pair, motion.x, motion.y, pose);
      glm::vec3 local = pose[toe].position;
      float c = std::cos(placement.w), sn = std::sin(placement.w);
      toeWorld.push_back(glm::vec3(placement.x + local.x * c + local.z * sn, local.y,
                                   placement.z - local.x * sn + local.z * c));
    }
    float lowest = 1e9f;
    for (auto& p : toeWorld) lowest = std::min(lowest, p.y);
    // Horizontal drift between consecutive frames while the toe is on the ground.
    float worstDrift = 0.0f;
    int planted = 0;
    for (size_t s = 1; s < toeWorld.size(); ++s) {
      if (toeWorld[s].y < lowest + 0.01f && toeWorld[s - 1].y < lowest + 0.01f) {
        ++planted;
        worstDrift =
            std::max(worstDrift, glm::length(glm::vec2(toeWorld[s].x - toeWorld[s - 1].x,
                                                       toeWorld[s].z - toeWorld[s - 1].z)));
      }
    }
    MESSAGE("w = ", w, ": ", planted, " planted frame pairs, worst toe drift per frame ",
            worstDrift * 100.0f, " cm");
    CHECK(planted >= 2);
    CHECK(worstDrift < 0.03f);
  }
}
