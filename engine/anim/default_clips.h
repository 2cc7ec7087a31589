#pragma once
// The built-in slow and fast run cycles (the parametric gait that also writes assets/*.bvh),
// ready to bake: the default scene needs no file on disk.
#include <filesystem>
#include <optional>

#include "anim/clip.h"
#include "anim/clip_prep.h"

namespace throng::anim {

struct ClipPair {
  Clip slow;
  Clip fast;
  std::string description;  // for logs: where the clips came from, loops and speeds
};

ClipPair defaultRunPair();

// --slow/--fast files: parsed, converted to metres, resampled, loops cut, phases aligned.
ClipPair loadClipPair(const std::filesystem::path& slow, const std::filesystem::path& fast,
                      const PairOptions& options = {});

}  // namespace throng::anim
