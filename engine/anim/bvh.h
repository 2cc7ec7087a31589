#pragma once
// BVH import (HIERARCHY + MOTION) and export. Errors name the file, the line and what was
// expected; the parser never crashes on malformed input.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "anim/clip.h"

namespace throng::anim {

// `sourceName` is used in error messages ("walk.bvh:12: expected ..."). Problems the file can
// be read despite (more motion lines than Frames: declares: the declared frames are used) go
// to `warnings`, or to the log as warnings when it is null.
RawClip parseBvh(std::string_view text, const std::string& sourceName,
                 std::vector<std::string>* warnings = nullptr);
RawClip loadBvh(const std::filesystem::path& path);

// Writes a clip as BVH text (every joint: 3 rotation channels in Z X Y order; root adds
// Xposition Yposition Zposition first). Used by the asset generator.
std::string formatBvh(const RawClip& clip);

}  // namespace throng::anim
