// Per-frame translations of non-root joints (Clip::animatedOffsets, the Bandai Namco hips)
// through every clip preparation step, and the prepared Bandai pair standing on the ground.
#include <algorithm>
#include <vector>

#include <doctest/doctest.h>

#include "anim/bvh.h"
#include "anim/clip_prep.h"
#include "anim/clip_prep_util.h"
#include "anim/motion_texture.h"
#include "clip_fixtures.h"
#include "core/error.h"
#include "test_support.h"

using namespace throng::anim;
using throng::test::lowestFootPoints;
using throng::test::periodicClip;
using throng::test::withAnimatedOffsets;

namespace {

const char* const kBandaiRun = "bvh/bandai_namco/dataset-1_run_normal_001.bvh";
const char* const kBandaiDash = "bvh/bandai_namco/dataset-1_dash_normal_001.bvh";

RawClip load(const char* relative) {
  return loadBvh(throng::test::sharedDataDir() / relative);
}

}  // namespace

TEST_CASE("animated offsets: forward kinematics, scaling, resampling and cutting follow them") {
  Clip base = periodicClip(40, 20);
  Clip moved = withAnimatedOffsets(base);
  REQUIRE(moved.animatedOffsets.size() == moved.rotations.size());
  // The bob moved from the root into its children: every other joint is where it was.
  float bob = 0.0f;
  for (int f = 0; f < base.frameCount; ++f) {
    std::vector<glm::vec3> before = prep::globalPositions(base, f);
    std::vector<glm::vec3> after = prep::globalPositions(moved, f);
    for (int j = 1; j < base.jointCount(); ++j)
      CHECK(glm::length(after[size_t(j)] - before[size_t(j)]) < 1e-5f);
    bob = std::max(bob, std::abs(moved.offset(f, 1).y - base.skeleton.joints[1].offset.y));
  }
  CHECK(bob > 0.02f);

  Clip scaled = scaleToMetres(moved, 0.01f);
  for (size_t i = 0; i < moved.animatedOffsets.size(); ++i)
    CHECK(scaled.animatedOffsets[i] == moved.animatedOffsets[i] * 0.01f);

  Clip up = resample(moved, 1.0f / 60.0f);
  REQUIRE(up.frameCount == 80);
  REQUIRE(up.animatedOffsets.size() == up.rotations.size());
  for (int j = 1; j < moved.jointCount(); ++j) {
    CHECK(up.offset(14, j) == moved.offset(7, j));
    CHECK(glm::length(up.offset(15, j) - 0.5f * (moved.offset(7, j) + moved.offset(8, j))) < 1e-6f);
    CHECK(up.offset(79, j) == moved.offset(39, j));  // not a cycle: the last frame holds
  }
  moved.cycleTravel = glm::vec3(0, 0, 4);
  Clip wrapped = resample(moved, 1.0f / 60.0f);
  // A cycle's frame after the last is frame 0 moved by the travel, its local offsets unmoved.
  CHECK(glm::length(wrapped.offset(79, 1) - 0.5f * (moved.offset(39, 1) + moved.offset(0, 1))) <
        1e-6f);

  Clip loop = cutLoop(moved, LoopCut{3, 23, 0});
  REQUIRE(loop.animatedOffsets.size() == loop.rotations.size());
  CHECK(loop.offset(0, 1) == moved.offset(3, 1));
  CHECK(loop.offset(19, 4) == moved.offset(22, 4));

  Clip broken = moved;
  broken.animatedOffsets.pop_back();
  CHECK_THROWS_AS(resample(broken, 1.0f / 60.0f), throng::Error);
}

TEST_CASE("closeSeam spreads the animated offsets' mismatch: the hips do not climb") {
  Clip clip = withAnimatedOffsets(periodicClip(40, 20));
  // The hips rise 2 mm a frame under a root whose height never changes (rise 0).
  for (int f = 0; f < clip.frameCount; ++f) {
    for (int j = 1; j < clip.jointCount(); ++j) {
      if (clip.skeleton.joints[size_t(j)].parent == 0)
        clip.animatedOffsets[size_t(f * clip.jointCount() + j)].y += 0.002f * float(f);
    }
  }
  LoopCut cut{3, 23, 0};
  Clip raw = cutLoop(clip, cut);
  Clip closed = closeSeam(clip, cut);
  CHECK(closed.cycleTravel.y == 0.0f);
  glm::vec3 gap = clip.offset(3, 1) - clip.offset(23, 1);
  CHECK(gap.y == doctest::Approx(-0.04f).epsilon(0.01));
  for (int k : {0, 5, 19}) {
    CAPTURE(k);
    glm::vec3 expected = raw.offset(k, 1) + (float(k) / 20.0f) * gap;
    CHECK(glm::length(closed.offset(k, 1) - expected) < 1e-6f);
  }
  // Across the seam the spine's height steps like any other frame, instead of dropping 4 cm.
  auto spineHeight = [](const Clip& c, int f) { return prep::globalPositions(c, f)[1].y; };
  float seamClosed = std::abs(spineHeight(closed, 19) - spineHeight(closed, 0));
  float step = 0.0f;
  for (int k = 1; k < 20; ++k)
    step = std::max(step, std::abs(spineHeight(closed, k) - spineHeight(closed, k - 1)));
  CHECK(std::abs(spineHeight(raw, 19) - spineHeight(raw, 0)) > 0.03f);
  CHECK(seamClosed < 1.1f * step);
}

TEST_CASE("findBestLoop, faceForwardZ and alignPhases carry the animated offsets") {
  Clip periodic = withAnimatedOffsets(periodicClip(70, 23));
  LoopCut cut = findBestLoop(periodic, 12, 48);
  CHECK(cut.length() == 23);
  CHECK(cut.error < 1e-3f);
  // The loop search weighs offsets in metres like the root height.
  Clip bumped = periodic;
  bumped.animatedOffsets[size_t(25 * bumped.jointCount() + 1)].y += 0.05f;
  CHECK(loopError(bumped, 2, 25) - loopError(periodic, 2, 25) ==
        doctest::Approx(0.05f).epsilon(0.02));

  Clip cycle = cutLoop(withAnimatedOffsets(periodicClip(40, 20, {1, 0, -1})), LoopCut{0, 20, 0});
  Clip faced = faceForwardZ(cycle);
  CHECK(faced.animatedOffsets == cycle.animatedOffsets);  // local to parents that turn
  for (int f = 0; f < cycle.frameCount; ++f)
    CHECK(prep::globalPositions(faced, f)[1].y ==
          doctest::Approx(prep::globalPositions(cycle, f)[1].y));

  const int frames = 24;
  Clip slow = cutLoop(withAnimatedOffsets(periodicClip(frames + 1, frames)), LoopCut{0, frames, 0});
  const int k = 7;
  Clip fast = slow;
  const size_t joints = size_t(slow.jointCount());
  for (int i = 0; i < frames; ++i) {  // fast[i] = slow[i - k]
    int source = i < k ? i - k + frames : i - k;
    glm::vec3 back = i < k ? -slow.cycleTravel : glm::vec3(0.0f);
    for (size_t j = 0; j < joints; ++j) {
      fast.rotations[size_t(i) * joints + j] = slow.rotations[size_t(source) * joints + j];
      fast.animatedOffsets[size_t(i) * joints + j] =
          slow.animatedOffsets[size_t(source) * joints + j];
    }
    fast.rootPositions[size_t(i)] = slow.rootPositions[size_t(source)] + back;
  }
  CHECK(alignPhases(slow, fast) == k);
  CHECK(fast.rotations == slow.rotations);
  CHECK(fast.animatedOffsets == slow.animatedOffsets);
}

TEST_CASE("preparePair on Bandai Namco: the hips bob and the feet reach the ground") {
  if (!throng::test::haveSharedData(kBandaiRun) || !throng::test::haveSharedData(kBandaiDash))
    return;
  PreparedPair pair = preparePair(load(kBandaiRun), load(kBandaiDash), PairOptions{});
  for (const Clip* clip : {&pair.slow, &pair.fast}) {
    CAPTURE(clip->name);
    REQUIRE(clip->animatedOffsets.size() == clip->rotations.size());
    const int hips = clip->skeleton.findJoint("Hips");
    REQUIRE(hips > 0);
    float hipsLow = 1e9f, hipsHigh = -1e9f;
    MotionTexture texture = bakeMotionTexture(*clip);
    for (int f = 0; f < clip->frameCount; ++f) {
      float y = prep::globalPositions(*clip, f)[size_t(hips)].y;
      hipsLow = std::min(hipsLow, y);
      hipsHigh = std::max(hipsHigh, y);
      CHECK(texture.offset(f, hips) == clip->offset(f, hips));  // what the GPU blends
    }
    // Measured: run 0.847–0.940 m, dash 0.825–0.894 m (the rest OFFSET says 0.940 always).
    CHECK(hipsHigh - hipsLow > 0.05f);
    CHECK(hipsLow < 0.87f);

    // Measured: lowest foot point over the cycle 0.011 m (run) and -0.018 m (dash), and a
    // foot within 4 cm of the ground in 14 and 12 of 21 frames. With the rest offset for the
    // hips it was 0.029 m and 0.050 m, in 2 and 0 frames: the characters floated.
    std::vector<float> lowest = lowestFootPoints(*clip);
    float minimum = *std::min_element(lowest.begin(), lowest.end());
    CHECK(minimum > -0.03f);
    CHECK(minimum < 0.025f);
    auto contact = std::count_if(lowest.begin(), lowest.end(), [](float y) { return y < 0.04f; });
    CHECK(float(contact) >= 0.4f * float(clip->frameCount));
  }
}
