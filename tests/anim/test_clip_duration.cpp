// Clip preparation is bounded by the clip's length: a tiny file with a huge frame time is an
// error at once, not hours of loop search (found by the BVH fuzzer).
#include <doctest/doctest.h>

#include <string>

#include "anim/bvh.h"
#include "anim/clip_prep.h"
#include "core/error.h"

using namespace throng;

TEST_CASE("clip preparation: a capture longer than 600 s is refused before the loop search") {
  const std::string bvh =
      "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition Zrotation "
      "Xrotation Yrotation\n"
      " JOINT Spine\n {\n  OFFSET 0 10 0\n  CHANNELS 3 Zrotation Xrotation Yrotation\n"
      "  End Site\n  {\n   OFFSET 0 10 0\n  }\n }\n}\nMOTION\nFrames: 3\nFrame Time: 3333\n"
      "0 90 0 0 0 0 0 0 0\n0 90 1 0 0 0 0 0 0\n0 90 2 0 0 0 0 0 0\n";
  anim::RawClip raw = anim::parseBvh(bvh, "slow.bvh");
  CHECK_THROWS_WITH_AS(anim::preparePair(raw, raw, {}), doctest::Contains("up to 600 s"), Error);
}
