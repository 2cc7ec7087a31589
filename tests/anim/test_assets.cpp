// The project's own clips: formatBvh, the parametric gait, and the committed assets/*.bvh
// (up to date, loadable, looping, no foot skate, the speeds they claim).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <doctest/doctest.h>

#include "cli_support.h"

#include "anim/bvh.h"
#include "anim/gait.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/math.h"
#include "test_support.h"

namespace fs = std::filesystem;
using namespace throng::anim;

namespace {

struct Variant {
  GaitParams params;
  double targetSpeed;  // m/s, what the brief asks for (independent of params.speed)
  double cadence;      // steps per second (a hop lands both feet: one step); 0 standing
};

std::vector<Variant> variants() {
  return {{slowRunGait(), 2.5, 2.6},  {fastRunGait(), 4.5, 3.0}, {slowWalkGait(), 1.0, 1.8},
          {fastWalkGait(), 1.6, 2.3}, {idleGait(), 0.0, 0.0},    {talkGait(), 0.0, 0.0},
          {slowHopGait(), 0.8, 1.5},  {fastHopGait(), 1.6, 1.36}};
}

bool standing(const Variant& v) { return v.params.kind == GaitKind::Stand; }
bool hopping(const Variant& v) { return v.params.kind == GaitKind::Hop; }

fs::path committed(const GaitParams& params) {
  return throng::test::sourceDir() / "assets" / (params.name + ".bvh");
}

Joint joint(const std::string& name, int parent, glm::vec3 offset, std::vector<Channel> channels) {
  Joint j;
  j.name = name;
  j.parent = parent;
  j.offset = offset;
  j.channels = std::move(channels);
  return j;
}

// Root with two children, the first of which has a child stored last: storage order
// (Root, A, B, C) differs from the depth-first order a BVH file needs (Root, A, C, B).
RawClip smallClip() {
  RawClip clip;
  clip.sourceName = "small.bvh";
  const std::vector<Channel> zxy = {Channel::Zrotation, Channel::Xrotation, Channel::Yrotation};
  clip.skeleton.joints = {
      joint("Root", -1, {0, 0, 0},
            {Channel::Xposition, Channel::Yposition, Channel::Zposition, Channel::Zrotation,
             Channel::Xrotation, Channel::Yrotation}),
      joint("A", 0, {0.1f, 0, 0}, zxy),
      joint("B", 0, {-0.1f, 0, 0}, {Channel::Xrotation, Channel::Yrotation, Channel::Zrotation}),
      joint("C", 1, {0, -0.5f, 0.25f}, zxy)};
  clip.skeleton.joints[3].endSite = glm::vec3(0, -0.125f, 0);
  clip.skeleton.joints[2].endSite = glm::vec3(0, 0, 1);
  clip.channelCount = 6 + 3 + 3 + 3;
  clip.frameCount = 2;
  clip.frameTime = 0.04f;
  clip.values = {1,  2,  3,  4,  5,  6,  7,  8,  9,  10,     11,    12,     13,     14,   15,
                 -1, -2, -3, -4, -5, -6, -7, -8, -9, -1e-9f, -0.5f, 1e-12f, 12.25f, 1e6f, -13.125f};
  return clip;
}

// Angle between two unit quaternions (either sign), radians.
double angleBetween(glm::vec4 a, glm::vec4 b) {
  double d = std::min(1.0, std::abs(double(glm::dot(a, b))));
  return 2.0 * std::acos(d);
}

// A clip of the given gait frames (any integers, frame n = frame 0 a cycle later).
RawClip clipOfFrames(const GaitParams& params, const std::vector<int>& frames) {
  RawClip clip = generateGait(params);
  clip.frameCount = int(frames.size());
  clip.values.clear();
  for (int f : frames) {
    for (double v : gaitFrame(params, f)) clip.values.push_back(float(v));
  }
  return clip;
}

// World positions of every joint at one frame of a clip.
std::vector<glm::dvec3> framePositions(const RawClip& clip, int frame) {
  std::span<const float> values(clip.values.data() + size_t(frame) * size_t(clip.channelCount),
                                size_t(clip.channelCount));
  return forwardKinematics(clip.skeleton, values);
}

}  // namespace

TEST_CASE("formatBvh writes depth first, with fixed decimals, and parseBvh reads it back") {
  RawClip clip = smallClip();
  const std::string text = formatBvh(clip);
  const std::string expected =
      "HIERARCHY\n"
      "ROOT Root\n"
      "{\n"
      "\tOFFSET 0.000000 0.000000 0.000000\n"
      "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
      "\tJOINT A\n"
      "\t{\n"
      "\t\tOFFSET 0.100000 0.000000 0.000000\n"
      "\t\tCHANNELS 3 Zrotation Xrotation Yrotation\n"
      "\t\tJOINT C\n"
      "\t\t{\n"
      "\t\t\tOFFSET 0.000000 -0.500000 0.250000\n"
      "\t\t\tCHANNELS 3 Zrotation Xrotation Yrotation\n"
      "\t\t\tEnd Site\n"
      "\t\t\t{\n"
      "\t\t\t\tOFFSET 0.000000 -0.125000 0.000000\n"
      "\t\t\t}\n"
      "\t\t}\n"
      "\t}\n"
      "\tJOINT B\n"
      "\t{\n"
      "\t\tOFFSET -0.100000 0.000000 0.000000\n"
      "\t\tCHANNELS 3 Xrotation Yrotation Zrotation\n"
      "\t\tEnd Site\n"
      "\t\t{\n"
      "\t\t\tOFFSET 0.000000 0.000000 1.000000\n"
      "\t\t}\n"
      "\t}\n"
      "}\n"
      "MOTION\n"
      "Frames: 2\n"
      "Frame Time: 0.04\n"
      // Root, A, C (values 13..15), then B (values 10..12): the file's joint order. A tiny
      // negative value is written as plain zero.
      "1.000000 2.000000 3.000000 4.000000 5.000000 6.000000 7.000000 8.000000 9.000000 "
      "13.000000 14.000000 15.000000 10.000000 11.000000 12.000000\n"
      "-1.000000 -2.000000 -3.000000 -4.000000 -5.000000 -6.000000 -7.000000 -8.000000 "
      "-9.000000 12.250000 1000000.000000 -13.125000 0.000000 -0.500000 0.000000\n";
  CHECK(text == expected);

  RawClip back = parseBvh(text, "small.bvh");
  REQUIRE(back.skeleton.jointCount() == 4);
  CHECK(back.skeleton.joints[2].name == "C");
  CHECK(back.skeleton.joints[2].parent == 1);
  CHECK(back.skeleton.joints[3].name == "B");
  CHECK(back.frameCount == 2);
  CHECK(back.frameTime == clip.frameTime);  // shortest round-trip text: the same float
  // Writing what was read gives the same text again.
  CHECK(formatBvh(back) == text);
}

TEST_CASE("formatBvh refuses a clip it cannot write faithfully") {
  RawClip clip = smallClip();
  SUBCASE("too few values") {
    clip.values.pop_back();
    CHECK_THROWS_WITH_AS(formatBvh(clip), doctest::Contains("small.bvh"), throng::Error);
  }
  SUBCASE("a value that is not finite") {
    clip.values[5] = std::nanf("");
    CHECK_THROWS_WITH_AS(formatBvh(clip), doctest::Contains("value 5 of frame 0"), throng::Error);
  }
  SUBCASE("a joint name with a space") {
    clip.skeleton.joints[1].name = "Left Arm";
    CHECK_THROWS_WITH_AS(formatBvh(clip), doctest::Contains("joint 1"), throng::Error);
  }
  SUBCASE("a child stored before its parent") {
    clip.skeleton.joints[1].parent = 3;
    CHECK_THROWS_AS(formatBvh(clip), throng::Error);
  }
  SUBCASE("no frame time") {
    clip.frameTime = 0.0f;
    CHECK_THROWS_AS(formatBvh(clip), throng::Error);
  }
}

TEST_CASE("the gait skeleton: 25 joints, about 1.75 m, the joints LOD spheres look for") {
  Skeleton skeleton = gaitSkeleton();
  const std::vector<std::string> names = {
      "Hips",        "Spine",          "Spine1",        "Spine2",    "Spine3",
      "Neck",        "Head",           "LeftShoulder",  "LeftArm",   "LeftForeArm",
      "LeftHand",    "LeftHandIndex",  "RightShoulder", "RightArm",  "RightForeArm",
      "RightHand",   "RightHandIndex", "LeftUpLeg",     "LeftLeg",   "LeftFoot",
      "LeftToeBase", "RightUpLeg",     "RightLeg",      "RightFoot", "RightToeBase"};
  REQUIRE(skeleton.jointCount() == 25);
  for (int j = 0; j < 25; ++j) CHECK(skeleton.joints[size_t(j)].name == names[size_t(j)]);
  for (const std::string name :
       {"Hips", "Spine1", "LeftForeArm", "RightForeArm", "LeftLeg", "RightLeg", "LeftFoot",
        "RightFoot", "LeftToeBase", "RightToeBase", "Head"}) {
    CAPTURE(name);
    CHECK(skeleton.findJoint(name) >= 0);
  }
  // Rest pose: the root at the origin; head top to toe is the standing height.
  std::vector<double> rest(size_t(6 + 3 * 24), 0.0);
  std::vector<glm::dvec3> p = forwardKinematics(skeleton, std::span<const double>(rest));
  const Joint& head = skeleton.joints[size_t(skeleton.findJoint("Head"))];
  double top = p[size_t(skeleton.findJoint("Head"))].y + head.endSite->y;
  double sole = p[size_t(skeleton.findJoint("LeftToeBase"))].y - 0.03;  // ball 3 cm up
  CHECK(top - sole == doctest::Approx(1.75).epsilon(0.03));
  // Left is +x when facing +z.
  CHECK(p[size_t(skeleton.findJoint("LeftArm"))].x > 0.1);
  CHECK(p[size_t(skeleton.findJoint("RightUpLeg"))].x < -0.05);
}

TEST_CASE("the committed assets are exactly what the generator writes now") {
  for (const Variant& v : variants()) {
    CAPTURE(v.params.name);
    const fs::path path = committed(v.params);
    REQUIRE_MESSAGE(fs::exists(path), path.string(), " is missing: run `throng assets generate`");
    RawClip clip = generateGait(v.params);
    CHECK(clip.sourceName == v.params.name + ".bvh");
    const std::string fresh = formatBvh(clip);
    CHECK_MESSAGE(throng::readTextFile(path) == fresh, path.string(),
                  " is out of date: run `throng assets generate --out assets`");
    CHECK(formatBvh(generateGait(v.params)) == fresh);  // deterministic
  }
}

TEST_CASE("the committed assets parse: 25 joints, one cycle at 30 fps, the target cadence") {
  for (const Variant& v : variants()) {
    CAPTURE(v.params.name);
    RawClip clip = loadBvh(committed(v.params));
    CHECK(clip.skeleton.jointCount() == 25);
    CHECK(clip.channelCount == 6 + 3 * 24);
    CHECK(clip.frameTime == doctest::Approx(1.0 / 30.0).epsilon(1e-6));
    // One cycle (two steps, one hop) at the target cadence, rounded to whole frames; standing: 2 s.
    if (standing(v)) {
      CHECK(clip.frameCount == 60);
    } else {
      const double steps = hopping(v) ? 1.0 : 2.0;
      CHECK(clip.frameCount == int(std::lround(steps / v.cadence * 30.0)));
      CHECK(clip.frameCount >= 20);
      CHECK(clip.frameCount <= 34);
    }
    CHECK(clip.skeleton.sameTopology(gaitSkeleton()));
    // The text keeps every value to within its last printed digit (plus float rounding).
    RawClip generated = generateGait(v.params);
    REQUIRE(generated.values.size() == clip.values.size());
    float worst = 0.0f;
    for (size_t i = 0; i < clip.values.size(); ++i) {
      worst = std::max(worst, std::abs(clip.values[i] - generated.values[i]));
    }
    CHECK(worst < 1e-5f);
  }
}

TEST_CASE("the gait loops: the frame after the last is frame 0 one cycle further on") {
  for (const Variant& v : variants()) {
    CAPTURE(v.params.name);
    const int n = v.params.cycleFrames;
    std::vector<int> frames;
    for (int f = 0; f <= n + 1; ++f) frames.push_back(f);
    Clip clip = toClip(clipOfFrames(v.params, frames));
    double seamStep = 0.0, largestStep = 0.0;
    for (int j = 0; j < clip.jointCount(); ++j) {
      CAPTURE(clip.skeleton.joints[size_t(j)].name);
      CHECK(angleBetween(clip.rotation(0, j), clip.rotation(n, j)) < 1e-3);
      CHECK(angleBetween(clip.rotation(1, j), clip.rotation(n + 1, j)) < 1e-3);
      seamStep = std::max(seamStep, angleBetween(clip.rotation(n - 1, j), clip.rotation(n, j)));
      for (int f = 0; f + 1 < n; ++f) {
        largestStep =
            std::max(largestStep, angleBetween(clip.rotation(f, j), clip.rotation(f + 1, j)));
      }
    }
    // Crossing the seam is no bigger a step than the ordinary frame-to-frame motion.
    CHECK(seamStep <= largestStep + 1e-4);
    const double travel = gaitCycleTravel(v.params);
    glm::vec3 shift = clip.rootPositions[size_t(n)] - clip.rootPositions[0];
    CHECK(std::abs(shift.x) < 1e-5);
    CHECK(std::abs(shift.y) < 1e-5);
    CHECK(shift.z == doctest::Approx(travel).epsilon(1e-5));
  }
}

TEST_CASE("the root travels along +z at the target speed") {
  for (const Variant& v : variants()) {
    CAPTURE(v.params.name);
    RawClip clip = loadBvh(committed(v.params));
    const int n = clip.frameCount;
    const double duration = n * double(clip.frameTime);
    // From the file alone: the mean speed over the frames it holds.
    const double first = clip.values[2],
                 last = clip.values[size_t(n - 1) * size_t(clip.channelCount) + 2];
    const double fileSpeed = (last - first) / ((n - 1) * double(clip.frameTime));
    const double cycleSpeed = gaitCycleTravel(v.params) / duration;
    if (standing(v)) {
      // No travel: the root only shifts its weight from foot to foot, within a few centimetres.
      CHECK(gaitCycleTravel(v.params) == 0.0);
      for (int f = 0; f < n; ++f) {
        CHECK(std::abs(clip.values[size_t(f) * size_t(clip.channelCount)]) < 0.03);
        CHECK(std::abs(clip.values[size_t(f) * size_t(clip.channelCount) + 2]) < 1e-6);
      }
      continue;
    }
    CHECK(std::abs(fileSpeed - v.targetSpeed) < 0.1 * v.targetSpeed);
    CHECK(std::abs(cycleSpeed - v.targetSpeed) < 0.1 * v.targetSpeed);
    MESSAGE(v.params.name, ": ", n, " frames, cycle travel ", gaitCycleTravel(v.params),
            " m, speed ", cycleSpeed, " m/s (frames alone: ", fileSpeed, " m/s), cadence ",
            2.0 / duration, " steps/s");
    for (int f = 1; f < n; ++f) {
      double dz = clip.values[size_t(f) * size_t(clip.channelCount) + 2] -
                  clip.values[size_t(f - 1) * size_t(clip.channelCount) + 2];
      CHECK(dz > 0.0);  // always forward, never a surge backwards
    }
  }
}

TEST_CASE("forwardKinematics agrees with toClip's quaternions (one Euler convention)") {
  RawClip raw = loadBvh(committed(fastRunGait()));
  Clip clip = toClip(raw);
  for (int f = 0; f < raw.frameCount; f += 3) {
    std::vector<glm::dvec3> fk = framePositions(raw, f);
    std::vector<glm::vec4> global(size_t(clip.jointCount()));
    std::vector<glm::vec3> position(size_t(clip.jointCount()));
    for (int j = 0; j < clip.jointCount(); ++j) {
      const Joint& joint = clip.skeleton.joints[size_t(j)];
      if (joint.parent < 0) {
        global[size_t(j)] = clip.rotation(f, j);
        position[size_t(j)] = clip.rootPositions[size_t(f)];
      } else {
        const size_t parent = size_t(joint.parent);
        position[size_t(j)] = position[parent] + throng::quatRotate(global[parent], joint.offset);
        global[size_t(j)] = throng::quatMul(global[parent], clip.rotation(f, j));
      }
      CHECK(glm::length(glm::dvec3(position[size_t(j)]) - fk[size_t(j)]) < 1e-4);
    }
  }
}

TEST_CASE("a planted foot does not skate; run and walk feet take turns, hops land together, standing feet stay") {
  for (const Variant& v : variants()) {
    CAPTURE(v.params.name);
    const GaitKind kind = v.params.kind;
    const bool run = kind == GaitKind::Alternate && v.params.stanceFraction < 0.5;
    const bool walk = kind == GaitKind::Alternate && !run;
    RawClip clip = loadBvh(committed(v.params));
    const int n = clip.frameCount;
    for (const std::string name : {"LeftFoot", "LeftToeBase", "RightFoot", "RightToeBase"}) {
      CAPTURE(name);
      const int j = clip.skeleton.findJoint(name);
      REQUIRE(j >= 0);
      std::vector<glm::dvec3> p;
      for (int f = 0; f < n; ++f) p.push_back(framePositions(clip, f)[size_t(j)]);
      // Planted: for a run the frames near the foot's lowest point; for the others (a swing
      // foot may skim the ground) the stance frames the gait defines.
      const bool left = name.rfind("Left", 0) == 0;
      const double offset = kind == GaitKind::Alternate && !left ? 0.5 : 0.0;
      double lowest = 1e9;
      for (const glm::dvec3& q : p) lowest = std::min(lowest, q.y);
      // Per stance (a stance may wrap from the clip's end to its start, a cycle's travel apart).
      glm::dvec2 lo[2] = {glm::dvec2(1e9), glm::dvec2(1e9)}, hi[2] = {glm::dvec2(-1e9), glm::dvec2(-1e9)};
      int planted = 0;
      for (int f = 0; f < n; ++f) {
        const double u = double(f) / n - offset;
        const bool stance = kind == GaitKind::Stand || u - std::floor(u) < v.params.stanceFraction;
        if (run ? p[size_t(f)].y > lowest + 0.01 : !stance) continue;
        ++planted;
        const int which = u < 0.0 ? 1 : 0;
        lo[which] = glm::min(lo[which], glm::dvec2(p[size_t(f)].x, p[size_t(f)].z));
        hi[which] = glm::max(hi[which], glm::dvec2(p[size_t(f)].x, p[size_t(f)].z));
      }
      double drift = 0.0;
      for (int k = 0; k < 2; ++k)
        if (hi[k].x >= lo[k].x) drift = std::max({drift, hi[k].x - lo[k].x, hi[k].y - lo[k].y});
      MESSAGE(v.params.name, " ", name, ": lowest ", lowest, " m, ", planted, " planted frames, horizontal drift ",
              drift * 100.0, " cm");
      CHECK(planted >= 2);  // the ankle rises early in a fast stance as the heel lifts
      // The ball of the foot stays put while planted; the ankle of a walk or hop rolls over it.
      const bool ball = name.find("ToeBase") != std::string::npos;
      CHECK(drift < (run ? 0.02 : ball ? 0.002 : kind == GaitKind::Stand ? 0.005 : 0.25));
    }
    // The ball of a planted foot sits on the ground (its joint 3 cm up), never below.
    const int leftBall = clip.skeleton.findJoint("LeftToeBase");
    const int rightBall = clip.skeleton.findJoint("RightToeBase");
    int leftDown = 0, rightDown = 0, bothUp = 0, bothDown = 0;
    for (int f = 0; f < n; ++f) {
      std::vector<glm::dvec3> p = framePositions(clip, f);
      const double l = p[size_t(leftBall)].y, r = p[size_t(rightBall)].y;
      CHECK(l > 0.029);
      CHECK(r > 0.029);
      const bool left = l < 0.032, right = r < 0.032;
      leftDown += left;
      rightDown += right;
      bothUp += !left && !right;
      bothDown += left && right;
      const double u = double(f) / n;
      if (kind == GaitKind::Stand) {
        CHECK(left);
        CHECK(right);
        continue;
      }
      // Left contact at phase 0; the right foot half a cycle later, or with it in a hop.
      if (f == 0) CHECK(left);
      if (f == 0 && run) CHECK(!right);
      if (u < v.params.stanceFraction) CHECK(left);
      if (kind == GaitKind::Hop) CHECK(left == right);
      if (kind == GaitKind::Alternate && u >= 0.5 && u < 0.5 + v.params.stanceFraction) CHECK(right);
    }
    if (run) CHECK(bothDown == 0);  // a run: never both feet on the ground
    if (run || kind == GaitKind::Hop) CHECK(bothUp >= 2);  // a flight phase after each step or hop
    if (walk) {
      CHECK(bothUp == 0);    // a walk: always a foot on the ground,
      CHECK(bothDown >= 4);  // and both at each change of foot
    }
    CHECK(std::abs(leftDown - rightDown) <= 1);
    MESSAGE(v.params.name, ": frames with the left foot down ", leftDown, ", right ", rightDown, ", both ", bothDown,
            ", neither ", bothUp, " of ", n);
  }
}

TEST_CASE("the standing pair differs where it should: talking lifts the hands well above idling") {
  RawClip idle = generateGait(idleGait()), talk = generateGait(talkGait());
  const int hand = idle.skeleton.findJoint("RightHand");
  REQUIRE(hand >= 0);
  double idleHighest = -1e9, talkHighest = -1e9;
  for (int f = 0; f < idle.frameCount; ++f) idleHighest = std::max(idleHighest, framePositions(idle, f)[size_t(hand)].y);
  for (int f = 0; f < talk.frameCount; ++f) talkHighest = std::max(talkHighest, framePositions(talk, f)[size_t(hand)].y);
  MESSAGE("highest right hand: idle ", idleHighest, " m, talk ", talkHighest, " m");
  CHECK(idleHighest < 0.95);               // hanging at the side
  CHECK(talkHighest > idleHighest + 0.2);  // raised in gestures
}

TEST_CASE("throng assets generate writes every clip, and a bad --out is an error") {
  const fs::path dir =
      fs::temp_directory_path() / ("throng_test_assets_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  throng::test::CommandResult run = throng::test::runThrong("assets generate --out '" + dir.string() + "'");
  CHECK(run.exitCode == 0);
  CHECK(run.output.find("run_slow.bvh: 25 joints, 23 frames") != std::string::npos);
  for (const Variant& v : variants()) {
    CAPTURE(v.params.name);
    const fs::path written = dir / (v.params.name + ".bvh");
    REQUIRE(fs::exists(written));
    CHECK(throng::readTextFile(written) == formatBvh(generateGait(v.params)));
  }
  // Only the clips and the scenes folder (its files: tests/scene): no temporary file left
  // behind by the atomic writes.
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) ==
        long(variants().size()) + 1);
  CHECK(fs::is_directory(dir / "scenes"));
  for (const auto& entry : fs::directory_iterator(dir / "scenes"))
    CHECK(entry.path().extension() == ".json");

  const fs::path notADir = dir / "run_slow.bvh";
  throng::test::CommandResult bad = throng::test::runThrong("assets generate --out '" + notADir.string() + "'");
  CHECK(bad.exitCode == 1);
  CHECK(bad.output.find("not a directory") != std::string::npos);
  fs::remove_all(dir);
}
