// Clip preparation: units, resampling, loop cutting, facing +z and phase alignment, on
// synthetic clips with known answers and on the real CMU and Bandai Namco captures.
#include <cmath>
#include <string>

#include <doctest/doctest.h>
#include <glm/gtc/quaternion.hpp>

#include "anim/bvh.h"
#include "anim/clip_prep.h"
#include "anim/clip_prep_util.h"
#include "clip_fixtures.h"
#include "core/error.h"
#include "core/math.h"
#include "test_support.h"

using namespace throng::anim;
using throng::kPi;
using throng::test::periodicClip;
using throng::test::personSkeleton;

namespace {

const char* const kCmuRun = "bvh/cmu/cmu_09_01_run.bvh";
const char* const kCmuRunJog = "bvh/cmu/cmu_35_17_runjog.bvh";
const char* const kCmuWalk = "bvh/cmu/cmu_12_01_walk.bvh";
const char* const kBandaiRun = "bvh/bandai_namco/dataset-1_run_normal_001.bvh";
const char* const kBandaiDash = "bvh/bandai_namco/dataset-1_dash_normal_001.bvh";
const char* const kBandaiWalk = "bvh/bandai_namco/dataset-1_walk_normal_002.bvh";

RawClip load(const char* relative) {
  return loadBvh(throng::test::sharedDataDir() / relative);
}

// The same clip after a calibration frame with every joint at identity (as CMU starts).
Clip withTPose(const Clip& clip) {
  Clip out = clip;
  out.frameCount += 1;
  out.rotations.insert(out.rotations.begin(), size_t(clip.jointCount()), glm::vec4(0, 0, 0, 1));
  out.rootPositions.insert(out.rootPositions.begin(), clip.rootPositions.front());
  return out;
}

float angleBetween(glm::vec4 a, glm::vec4 b) {
  return prep::rotationAngle(a, b);
}

float speed(const Clip& clip) {
  return glm::length(clip.cycleTravel) / clip.duration();
}

int lowestFootFrame(const Clip& clip) {
  int foot = clip.skeleton.findJoint("LeftFoot");
  if (foot < 0) foot = clip.skeleton.findJoint("Foot_L");
  REQUIRE(foot >= 0);
  int best = 0;
  float lowest = 1e9f;
  for (int f = 0; f < clip.frameCount; ++f) {
    float y = prep::globalPositions(clip, f)[size_t(foot)].y;
    if (y < lowest) lowest = y, best = f;
  }
  return best;
}

Clip prepared(const char* relative) {
  RawClip raw = load(relative);
  Clip clip = toClip(raw);
  return resample(scaleToMetres(clip, detectUnits(clip.skeleton).metresPerUnit), 1.0f / 30.0f);
}

}  // namespace

TEST_CASE("detectUnits: synthetic skeletons in metres, inches, lying down and odd units") {
  UnitsGuess metres = detectUnits(personSkeleton());
  CHECK(metres.label == "metres");
  CHECK(metres.metresPerUnit == 1.0f);
  CHECK(metres.heightInUnits == doctest::Approx(1.75f).epsilon(1e-4));

  Clip clip = periodicClip(2, 10);
  Skeleton inches = scaleToMetres(clip, 1.0f / 0.0254f).skeleton;
  CHECK(detectUnits(inches).label == "inches");
  CHECK(detectUnits(inches).metresPerUnit == doctest::Approx(0.0254f));

  // Bones laid along +x (Bandai Namco style): the head-to-ankle chain stands for the height.
  Skeleton lying = scaleToMetres(clip, 100.0f).skeleton;
  for (Joint& joint : lying.joints) {
    if (joint.parent > 0) joint.offset = glm::vec3(glm::length(joint.offset), 0, 0);
    if (joint.endSite) joint.endSite = glm::vec3(glm::length(*joint.endSite), 0, 0);
  }
  UnitsGuess lyingGuess = detectUnits(lying);
  CHECK(lyingGuess.label == "centimetres");
  float chain = 20 + 35 + 25 + glm::length(glm::vec2(10, 5)) + 45 + 42;  // head top to ankle
  CHECK(lyingGuess.heightInUnits == doctest::Approx(chain).epsilon(1e-3));

  Skeleton odd = scaleToMetres(clip, 10.0f).skeleton;  // 17.5 units: no known unit
  UnitsGuess oddGuess = detectUnits(odd);
  CHECK(oddGuess.label == "unknown");
  CHECK(oddGuess.metresPerUnit == doctest::Approx(0.1f).epsilon(1e-3));
}

TEST_CASE("detectUnits: Bandai Namco is in centimetres, CMU in its own units") {
  for (const char* file : {kBandaiRun, kBandaiDash, kBandaiWalk}) {
    if (!throng::test::haveSharedData(file)) return;
    UnitsGuess guess = detectUnits(load(file).skeleton);
    CAPTURE(file);
    CHECK(guess.label == "centimetres");
    CHECK(guess.metresPerUnit == 0.01f);
    CHECK(guess.heightInUnits > 130.0f);  // head top to ankle along the bones: 144.5 cm
    CHECK(guess.heightInUnits < 190.0f);
  }
  for (const char* file : {kCmuRun, kCmuRunJog, kCmuWalk}) {
    if (!throng::test::haveSharedData(file)) return;
    UnitsGuess guess = detectUnits(load(file).skeleton);
    CAPTURE(file);
    CHECK(guess.label == "cmu-units");
    CHECK(guess.metresPerUnit == doctest::Approx(0.056444f));
    CHECK(guess.heightInUnits > 22.0f);  // 24.2 (subject 12) to 26.5 (subject 35)
    CHECK(guess.heightInUnits < 30.0f);
  }
}

TEST_CASE("scaleToMetres scales offsets, End Sites, root positions and travel") {
  Clip clip = periodicClip(5, 10);
  clip.cycleTravel = glm::vec3(1, 2, 3);
  Clip scaled = scaleToMetres(clip, 0.01f);
  CHECK(scaled.skeleton.joints[2].offset.y == doctest::Approx(0.0035f));
  CHECK(scaled.skeleton.joints[2].endSite->y == doctest::Approx(0.002f));
  CHECK(scaled.rootPositions[4].z == doctest::Approx(clip.rootPositions[4].z * 0.01f));
  CHECK(scaled.cycleTravel.z == doctest::Approx(0.03f));
  CHECK(scaled.rotations == clip.rotations);
  CHECK_THROWS_AS(scaleToMetres(clip, 0.0f), throng::Error);
}

TEST_CASE("resample keeps the duration, hits shared frames exactly and slerps between") {
  Clip clip = periodicClip(120, 47);
  clip.frameTime = 1.0f / 120.0f;
  Clip down = resample(clip, 1.0f / 30.0f);
  CHECK(down.frameCount == 30);
  CHECK(down.duration() == doctest::Approx(clip.duration()));
  CHECK(down.frameTime == doctest::Approx(1.0f / 30.0f));
  for (int k = 0; k < down.frameCount; ++k) {
    CHECK(down.rootPositions[size_t(k)] == clip.rootPositions[size_t(4 * k)]);
    for (int j = 0; j < clip.jointCount(); ++j)
      CHECK(down.rotation(k, j) == clip.rotation(4 * k, j));
  }
  Clip up = resample(clip, 1.0f / 240.0f);
  REQUIRE(up.frameCount == 240);
  glm::vec4 mid = throng::slerpShortest(clip.rotation(10, 3), clip.rotation(11, 3), 0.5f);
  CHECK(angleBetween(up.rotation(21, 3), mid) < 1e-5f);
  CHECK(up.rootPositions[21].z ==
        doctest::Approx(0.5f * (clip.rootPositions[10].z + clip.rootPositions[11].z)));
  // Not a cycle: past the last frame it holds. A cycle wraps to frame 0 moved by the travel.
  CHECK(up.rootPositions[239] == clip.rootPositions[119]);
  clip.cycleTravel = glm::vec3(0, 0, 10);
  Clip cyclic = resample(clip, 1.0f / 240.0f);
  CHECK(cyclic.rootPositions[239].z == doctest::Approx(0.5f * (clip.rootPositions[119].z + 10.0f)));
  CHECK(cyclic.cycleTravel == clip.cycleTravel);
  CHECK_THROWS_AS(resample(clip, 0.0f), throng::Error);
  CHECK_THROWS_AS(resample(clip, 1e-9f), throng::Error);  // 1e9 frames: refused, not allocated
  Clip empty = clip;
  empty.frameCount = 0;
  empty.rotations.clear();
  empty.rootPositions.clear();
  CHECK_THROWS_AS(resample(empty, 0.1f), throng::Error);

  if (!throng::test::haveSharedData(kCmuRun)) return;
  Clip cmu = toClip(load(kCmuRun));
  Clip cmu30 = resample(cmu, 1.0f / 30.0f);
  CHECK(cmu30.frameCount == 37);  // 149 frames at 120 fps = 1.2417 s
  CHECK(cmu30.duration() == doctest::Approx(cmu.duration()));
}

TEST_CASE("findBestLoop finds the exact period of a periodic clip, one cycle not two") {
  Clip clip = periodicClip(70, 23);
  LoopCut cut = findBestLoop(clip, 12, 48);
  CHECK(cut.length() == 23);
  CHECK(cut.error < 1e-3f);
  CHECK(loopError(clip, cut.start, cut.end) == doctest::Approx(cut.error));
  CHECK(loopError(clip, 5, 5 + 11) > 0.2f);    // half a cycle: the legs are swapped
  LoopCut twice = findBestLoop(clip, 30, 48);  // one cycle excluded: two are the best
  CHECK(twice.length() == 46);
  CHECK(twice.error < 1e-3f);
  // Two cycles match exactly and one only nearly: one is still the answer.
  Clip wobbly = periodicClip(70, 23, {0, 0, 1}, 3.0f, 0.02f);
  CHECK(loopError(wobbly, 2, 48) < 1e-3f);
  CHECK(loopError(wobbly, 2, 25) > 2e-3f);
  CHECK(findBestLoop(wobbly, 12, 48).length() == 23);

  Clip calibrated = withTPose(clip);
  CHECK(prep::firstUsableFrame(calibrated) == 1);
  CHECK(prep::firstUsableFrame(clip) == 0);
  LoopCut skipped = findBestLoop(calibrated, 12, 48);
  CHECK(skipped.start >= 1);
  CHECK(skipped.length() == 23);

  CHECK_THROWS_AS(findBestLoop(clip, 70, 80), throng::Error);
  CHECK_THROWS_AS(findBestLoop(clip, 20, 10), throng::Error);
}

TEST_CASE("findBestLoop on CMU runs: one gait cycle, much closer than a random pair") {
  for (const char* file : {kCmuRun, kCmuRunJog}) {
    if (!throng::test::haveSharedData(file)) return;
    Clip clip = prepared(file);
    LoopCut cut = findBestLoop(clip, 12, 48);
    // Measured: 09_01 frames 12..34 (22, error 0.146), 35_17 frames 15..38 (23, 0.107).
    double sum = 0;
    int pairs = 0;
    for (int a = 1; a < clip.frameCount; a += 2) {
      for (int b = a + 1; b < clip.frameCount; b += 3, ++pairs) sum += loopError(clip, a, b);
    }
    CAPTURE(file);
    CAPTURE(cut.start);
    CAPTURE(cut.end);
    CHECK(cut.start >= 1);  // the T-pose frame is never part of a loop
    CHECK(cut.length() >= 18);
    CHECK(cut.length() <= 26);
    CHECK(cut.error < 0.2f);
    CHECK(cut.error < 0.4 * sum / pairs);  // random pairs: 0.44–0.53
  }
}

TEST_CASE("cutLoop and closeSeam cut a cycle and its travel") {
  Clip clip = periodicClip(40, 20);
  Clip loop = cutLoop(clip, LoopCut{3, 23, 0});
  CHECK(loop.frameCount == 20);
  CHECK(loop.rotation(0, 4) == clip.rotation(3, 4));
  CHECK(loop.rootPositions[19] == clip.rootPositions[22]);
  CHECK(loop.cycleTravel.z == doctest::Approx(3.0f * 20 / 30));
  CHECK(std::abs(loop.cycleTravel.y) < 1e-6f);
  CHECK_THROWS_AS(cutLoop(clip, LoopCut{3, 40, 0}), throng::Error);

  // A cut one frame short of the period leaves a mismatch; closeSeam spreads it so that the
  // step across the seam is no larger than the steps inside the cycle.
  LoopCut shortCut{3, 22, 0};
  Clip raw = cutLoop(clip, shortCut);
  Clip closed = closeSeam(clip, shortCut);
  CHECK(closed.cycleTravel.y == 0.0f);
  float rise = clip.rootPositions[22].y - clip.rootPositions[3].y;
  CHECK(std::abs(rise) > 0.005f);
  CHECK(closed.rootPositions[18].y == doctest::Approx(raw.rootPositions[18].y - rise * 18 / 19));
  CHECK(closed.rotation(0, 3) == clip.rotation(3, 3));
  float seamBefore = angleBetween(raw.rotation(18, 3), clip.rotation(3, 3));
  float seamAfter = angleBetween(closed.rotation(18, 3), closed.rotation(0, 3));
  float innerStep = angleBetween(clip.rotation(10, 3), clip.rotation(11, 3));
  CHECK(seamBefore > 1.5f * innerStep);
  CHECK(seamAfter < 1.2f * innerStep);
}

TEST_CASE("faceForwardZ turns the travel onto +z and starts above the origin") {
  glm::vec3 direction(1, 0, -1);
  Clip clip = periodicClip(40, 20, direction);
  for (glm::vec3& p : clip.rootPositions) p += glm::vec3(5, 0, 7);
  Clip cycle = cutLoop(clip, LoopCut{0, 20, 0});
  Clip faced = faceForwardZ(cycle);
  float travel = glm::length(cycle.cycleTravel);
  CHECK(faced.cycleTravel.x == doctest::Approx(0).epsilon(1e-5));
  CHECK(faced.cycleTravel.z == doctest::Approx(travel));
  CHECK(faced.rootPositions[0].x == doctest::Approx(0));
  CHECK(faced.rootPositions[0].z == doctest::Approx(0));
  CHECK(faced.rootPositions[0].y == doctest::Approx(cycle.rootPositions[0].y));
  CHECK(faced.rootPositions[7].z > faced.rootPositions[3].z);
  CHECK(std::abs(faced.rootPositions[7].x) < 1e-4f);
  // The body turns with the path: the same clip built facing +z has the same root rotation.
  Clip straight = periodicClip(40, 20);
  CHECK(angleBetween(faced.rotation(5, 0), straight.rotation(5, 0)) < 1e-4f);
  CHECK(faced.rotation(5, 3) == cycle.rotation(5, 3));  // only the root turns

  Clip raw = clip;  // not a cycle: the net travel decides
  Clip facedRaw = faceForwardZ(raw);
  glm::vec3 net = facedRaw.rootPositions.back() - facedRaw.rootPositions.front();
  CHECK(std::abs(net.x) < 1e-4f);
  CHECK(net.z > 0.0f);
}

TEST_CASE("alignPhases recovers a known frame shift") {
  const int frames = 24;
  Clip slow = cutLoop(periodicClip(frames + 1, frames), LoopCut{0, frames, 0});
  for (int k : {1, 5, 13, 23}) {
    Clip fast = slow;
    for (int i = 0; i < frames; ++i) {  // fast[i] = slow[i - k], continuous across the wrap
      int source = i - k;
      glm::vec3 back(0.0f);
      if (source < 0) source += frames, back = -slow.cycleTravel;
      for (int j = 0; j < slow.jointCount(); ++j) {
        fast.rotations[size_t(i * slow.jointCount() + j)] = slow.rotation(source, j);
      }
      fast.rootPositions[size_t(i)] = slow.rootPositions[size_t(source)] + back;
    }
    CAPTURE(k);
    glm::vec3 start = fast.rootPositions[0];
    CHECK(alignPhases(slow, fast) == k);
    CHECK(fast.rotations == slow.rotations);
    CHECK(fast.rootPositions[0].z == doctest::Approx(start.z));  // frame 0 stays in place
    for (int i = 1; i < frames; ++i) {
      glm::vec3 step = fast.rootPositions[size_t(i)] - fast.rootPositions[size_t(i - 1)];
      glm::vec3 expected = slow.rootPositions[size_t(i)] - slow.rootPositions[size_t(i - 1)];
      CHECK(glm::length(step - expected) < 1e-5f);
    }
  }
  Clip same = slow;
  CHECK(alignPhases(slow, same) == 0);

  Clip other = slow;
  other.name = "other";
  other.skeleton.joints.pop_back();
  other.rotations.resize(size_t(other.frameCount * other.jointCount()));
  try {
    alignPhases(slow, other);
    FAIL("expected an Error");
  } catch (const throng::Error& e) {
    std::string message = e.what();
    CHECK(message.find("periodic") != std::string::npos);
    CHECK(message.find("other") != std::string::npos);
    CHECK(message.find("9 joints") != std::string::npos);
  }
}

TEST_CASE("preparePair on Bandai Namco run + dash and on CMU 35_17 + 09_01") {
  struct Case {
    const char* slow;
    const char* fast;
    float slowSpeed, fastSpeed;  // the data README's rough figures, m/s
  };
  for (Case c :
       {Case{kBandaiRun, kBandaiDash, 2.5f, 4.1f}, Case{kCmuRunJog, kCmuRun, 3.2f, 3.5f}}) {
    if (!throng::test::haveSharedData(c.slow) || !throng::test::haveSharedData(c.fast)) return;
    PreparedPair pair = preparePair(load(c.slow), load(c.fast), PairOptions{});
    CAPTURE(c.slow);
    CHECK(pair.slow.frameCount == pair.fast.frameCount);
    CHECK(pair.slow.frameCount >= 18);  // measured: 21 (Bandai), 23 (CMU)
    CHECK(pair.slow.frameCount <= 26);
    for (const Clip* clip : {&pair.slow, &pair.fast}) {
      CHECK(std::abs(clip->cycleTravel.x) < 1e-3f);
      CHECK(clip->cycleTravel.y == 0.0f);
      CHECK(clip->cycleTravel.z > 1.5f);
      CHECK(clip->rootPositions[0].x == doctest::Approx(0).epsilon(1e-6));
      CHECK(clip->rootPositions[0].z == doctest::Approx(0).epsilon(1e-6));
    }
    // Measured: Bandai 2.61 / 4.31 m/s, CMU 3.19 / 3.60 m/s.
    CHECK(speed(pair.slow) > 0.6f * c.slowSpeed);
    CHECK(speed(pair.slow) < 1.4f * c.slowSpeed);
    CHECK(speed(pair.fast) > 0.6f * c.fastSpeed);
    CHECK(speed(pair.fast) < 1.4f * c.fastSpeed);
    CHECK(speed(pair.fast) > speed(pair.slow));
    // Left-foot contact at the same frame (±2) in both.
    int gap = std::abs(lowestFootFrame(pair.slow) - lowestFootFrame(pair.fast));
    CHECK(std::min(gap, pair.slow.frameCount - gap) <= 2);
  }
  if (!throng::test::haveSharedData(kBandaiRun)) return;
  PreparedPair bandai = preparePair(load(kBandaiRun), load(kBandaiDash), PairOptions{});
  CHECK(bandai.slowLoop.start == 0);  // the files hold one cycle, last frame = first frame
  CHECK(bandai.slowLoop.end == 23);
  CHECK(bandai.fastLoop.end == 19);
}

TEST_CASE("preparePair: options and a mismatched pair") {
  if (!throng::test::haveSharedData(kBandaiRun) || !throng::test::haveSharedData(kCmuRun)) return;
  PairOptions whole;
  whole.cutLoops = false;
  whole.metresPerUnit = 0.02f;  // given units win over the detected centimetres
  PreparedPair pair = preparePair(load(kBandaiRun), load(kBandaiDash), whole);
  CHECK(pair.slowLoop.length() == 24);
  CHECK(pair.slow.frameCount == 22);
  // The whole file is the cycle: travel = mean velocity (2 × 2 m over 23 frame steps) × 24.
  CHECK(speed(pair.slow) == doctest::Approx(4.0f / (23.0f / 30.0f)).epsilon(0.01));

  try {
    preparePair(load(kBandaiRun), load(kCmuRun), PairOptions{});
    FAIL("expected an Error");
  } catch (const throng::Error& e) {
    std::string message = e.what();
    CHECK(message.find("dataset-1_run_normal_001.bvh") != std::string::npos);
    CHECK(message.find("cmu_09_01_run.bvh") != std::string::npos);
    CHECK(message.find("22 joints") != std::string::npos);
    CHECK(message.find("31") != std::string::npos);
  }
}
