// BVH text → RawClip → Clip, then the clip preparation a capture goes through before baking:
// unit detection, metres, resampling to 30 fps, the loop search and the slow/fast pair
// preparation (the clip paired with itself).
#include <algorithm>

#include "anim/bvh.h"
#include "anim/clip_prep.h"
#include "fuzz_support.h"

using namespace throng;

namespace {
constexpr int kShortestLoop = 15;
constexpr int kLongestLoop = 45;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::expectParseOrError([&] {
    const anim::RawClip raw = anim::parseBvh(fuzz::asText(data, size), "fuzz.bvh");
    const anim::UnitsGuess units = anim::detectUnits(raw.skeleton);
    const anim::Clip clip =
        anim::resample(anim::scaleToMetres(anim::toClip(raw), units.metresPerUnit), 1.0f / 30.0f);
    // The search `throng clip info --loop` runs: cycles of 15 to 45 frames at 30 fps.
    const int maxFrames = std::min(kLongestLoop, clip.frameCount - 1);
    if (maxFrames >= 2) anim::findBestLoop(clip, std::min(kShortestLoop, maxFrames), maxFrames);
    anim::PairOptions options;
    options.cutLoops = size % 2 == 0;  // both paths of the preparation, by input
    anim::preparePair(raw, raw, options);
  });
  return 0;
}
