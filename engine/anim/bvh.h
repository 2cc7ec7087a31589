#pragma once
// BVH import (HIERARCHY + MOTION) and export. Errors name the file, the line and what was
// expected; the parser never crashes on malformed input.
#include <filesystem>
#include <string>
#include <string_view>

#include "anim/clip.h"

namespace throng::anim {

// `sourceName` is used in error messages ("walk.bvh:12: expected ...").
RawClip parseBvh(std::string_view text, const std::string& sourceName);
RawClip loadBvh(const std::filesystem::path& path);

// Writes a clip as BVH text (every joint: 3 rotation channels in Z X Y order; root adds
// Xposition Yposition Zposition first). Used by the asset generator.
std::string formatBvh(const RawClip& clip);

}  // namespace throng::anim
