#pragma once
// The built-in clip pairs (the parametric gait that also writes assets/*.bvh), ready to bake:
// the default scene needs no file on disk.
#include <filesystem>
#include <optional>
#include <vector>

#include "anim/clip.h"
#include "anim/clip_prep.h"

namespace throng::anim {

struct ClipPair {
  Clip slow;
  Clip fast;
  std::string description;  // for logs: where the clips came from, loops and speeds
};

ClipPair defaultRunPair();
ClipPair defaultWalkPair();  // slow and fast walk
ClipPair defaultTalkPair();  // idle (w = 0) and talk (w = 1), standing: no travel
ClipPair defaultJumpPair();  // slow and fast forward hops

// The pair of each storyboard clip set, in the storyboard's action order: walk, run, talk, jump.
std::vector<ClipPair> defaultClipSets();

// --slow/--fast files: parsed, converted to metres, resampled, loops cut, phases aligned.
ClipPair loadClipPair(const std::filesystem::path& slow, const std::filesystem::path& fast,
                      const PairOptions& options = {});

}  // namespace throng::anim
