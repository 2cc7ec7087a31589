#pragma once
// Synthesized animation as glTF 2.0 binary (.glb), written with tinygltf: per character a node
// tree of its joints (translation and rotation animated at the clip's frame rate, linear
// interpolation) with a small bone mesh on each bone so any viewer shows the figure, and one
// animation holding every character's channels.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "anim/animation_export.h"

namespace throng::anim {

// The .glb bytes. Throws Error when there is nothing to write or the characters' frame counts
// or frame times differ.
std::vector<uint8_t> formatGlb(const std::vector<JointAnimation>& characters);

// Written to a temporary name and renamed when complete.
void writeGlb(const std::filesystem::path& path, const std::vector<JointAnimation>& characters);

}  // namespace throng::anim
