// preparePair's errors name the BVH file they concern (a Clip keeps only the file's stem).
#include <string>

#include <doctest/doctest.h>

#include "anim/bvh.h"
#include "anim/clip_prep.h"
#include "core/error.h"

using namespace throng::anim;

namespace {

// A chain of `joints` joints 0.3 units apart, `frames` frames of `frameTime` seconds.
std::string chainBvh(int joints, int frames, const char* frameTime) {
  std::string text =
      "HIERARCHY\nROOT j0\n{\nOFFSET 0 0 0\n"
      "CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n";
  for (int j = 1; j < joints; ++j)
    text += "JOINT j" + std::to_string(j) +
            "\n{\nOFFSET 0 0.3 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
  for (int j = 0; j < joints; ++j) text += "}\n";
  text += "MOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: " + frameTime + "\n";
  for (int f = 0; f < frames; ++f) {
    text += "0 0 " + std::to_string(f) + " ";
    for (int j = 0; j < joints * 3; ++j) text += "0 ";
    text += "\n";
  }
  return text;
}

std::string errorOf(const RawClip& slow, const RawClip& fast, const PairOptions& options) {
  try {
    preparePair(slow, fast, options);
  } catch (const throng::Error& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("preparePair: more joints than the pose pass supports names the BVH file") {
  const RawClip big = parseBvh(chainBvh(65, 3, "0.0333333"), "big_skeleton.bvh");
  const std::string message = errorOf(big, big, PairOptions{});
  CAPTURE(message);
  CHECK(message.rfind("big_skeleton.bvh: 65 joints; the pose pass supports 1..64 joints", 0) == 0);
  const RawClip ok = parseBvh(chainBvh(64, 40, "0.0333333"), "ok_skeleton.bvh");
  PairOptions options;
  options.metresPerUnit = 0.1f;
  options.cutLoops = false;
  CHECK(preparePair(ok, ok, options).slow.jointCount() == 64);
}

TEST_CASE("preparePair: a clip too long to prepare names the BVH file") {
  // 2 frames of 600,000 s at 30 fps would be 36 million frames: refused by its length first.
  const RawClip slow = parseBvh(chainBvh(3, 2, "600000"), "/data/very_slow.bvh");
  const RawClip fast = parseBvh(chainBvh(3, 2, "0.0333333"), "/data/fast.bvh");
  PairOptions options;
  options.metresPerUnit = 0.1f;
  const std::string message = errorOf(slow, fast, options);
  CAPTURE(message);
  CHECK(message.rfind("/data/very_slow.bvh: clip very_slow: 2 frames of 600000 s", 0) == 0);
  CHECK(message.find("clips of up to 600 s are prepared") != std::string::npos);
}
