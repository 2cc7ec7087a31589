#pragma once
// The project's example scene files (assets/scenes/), written by `throng assets generate`: a
// test checks that the committed files are exactly what this code writes.
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_file.h"

namespace throng::scene {

// (file name, scene) pairs.
std::vector<std::pair<std::string, SceneFile>> exampleScenes();

}  // namespace throng::scene
