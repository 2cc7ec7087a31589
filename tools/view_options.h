#pragma once
// Options of `throng view`: the scene options shared with `throng render`, plus the window's.
#include <string>

#include "scene_options.h"

namespace throng::tools {

struct ViewOptions {
  SceneOptions scene;
  int frames = 0;          // 0: until the window is closed
  std::string screenshot;  // saved after the last of `frames`
  std::string inputScript;
  std::string clock;  // "real" or "fixed"; empty: fixed with --frames, else real
  bool vsync = true;
  bool panel = true;
  bool validation = false;
  bool printStats = false;
};

}  // namespace throng::tools
