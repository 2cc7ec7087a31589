#include "anim/default_clips.h"

#include "anim/bvh.h"
#include "anim/gait.h"
#include "core/error.h"

namespace throng::anim {
namespace {
Clip gaitClip(const GaitParams& params) {
  Clip clip = toClip(generateGait(params));
  clip.name = params.name;
  clip.cycleTravel = glm::vec3(0.0f, 0.0f, static_cast<float>(gaitCycleTravel(params)));
  return clip;
}

float speedOf(const Clip& clip) { return glm::length(clip.cycleTravel) / clip.duration(); }

ClipPair gaitPair(const GaitParams& slow, const GaitParams& fast, const char* what) {
  ClipPair pair{gaitClip(slow), gaitClip(fast), {}};
  pair.description = concat("built-in ", what, ": slow ", speedOf(pair.slow), " m/s, fast ", speedOf(pair.fast), " m/s");
  return pair;
}
}  // namespace

ClipPair defaultRunPair() { return gaitPair(slowRunGait(), fastRunGait(), "run cycles"); }
ClipPair defaultWalkPair() { return gaitPair(slowWalkGait(), fastWalkGait(), "walk cycles"); }
ClipPair defaultTalkPair() { return gaitPair(idleGait(), talkGait(), "idle/talk cycles"); }
ClipPair defaultJumpPair() { return gaitPair(slowHopGait(), fastHopGait(), "hop cycles"); }

std::vector<ClipPair> defaultClipSets() {
  std::vector<ClipPair> sets;
  sets.push_back(defaultWalkPair());
  sets.push_back(defaultRunPair());
  sets.push_back(defaultTalkPair());
  sets.push_back(defaultJumpPair());
  return sets;
}

ClipPair loadClipPair(const std::filesystem::path& slow, const std::filesystem::path& fast,
                      const PairOptions& options) {
  RawClip slowRaw = loadBvh(slow);
  RawClip fastRaw = loadBvh(fast);
  PreparedPair prepared = preparePair(slowRaw, fastRaw, options);
  ClipPair pair{std::move(prepared.slow), std::move(prepared.fast), {}};
  pair.description = concat(slow.filename().string(), " (loop ", prepared.slowLoop.start, "..", prepared.slowLoop.end,
                            ", ", speedOf(pair.slow), " m/s) + ", fast.filename().string(), " (loop ",
                            prepared.fastLoop.start, "..", prepared.fastLoop.end, ", ", speedOf(pair.fast), " m/s)");
  return pair;
}

}  // namespace throng::anim
