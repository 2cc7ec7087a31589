// BVH text → RawClip → Clip, then the clip preparation a capture goes through before baking:
// unit detection, metres, resampling to 30 fps, the loop search and the slow/fast pair
// preparation (the clip paired with itself).
#include "anim/bvh.h"
#include "anim/clip_prep.h"
#include "fuzz_support.h"

using namespace throng;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::expectParseOrError([&] {
    const anim::RawClip raw = anim::parseBvh(fuzz::asText(data, size), "fuzz.bvh");
    const anim::UnitsGuess units = anim::detectUnits(raw.skeleton);
    const anim::Clip clip =
        anim::resample(anim::scaleToMetres(anim::toClip(raw), units.metresPerUnit), 1.0f / 30.0f);
    if (clip.frameCount >= 3) anim::findBestLoop(clip, 2, clip.frameCount - 1);
    anim::PairOptions options;
    options.cutLoops = size % 2 == 0;  // both paths of the preparation, by input
    anim::preparePair(raw, raw, options);
  });
  return 0;
}
