#pragma once
// The storyboard paper's own experiment as a scene: a subway corridor (two long walls, both
// ends open) filled with a storyboard quilted to its size — people walking both ways, hurrying,
// standing and talking in groups — whose walkers head for the far end their glyph faces and
// avoid each other and the walls. The sample storyboard is made in code (storyboard/example.h),
// so the scene needs no file.
#include <cstdint>

#include "scene/scene.h"

namespace throng::scene {

struct CorridorDescription {
  float length = 60.0f;   // metres along x, centred at the origin
  float width = 15.0f;    // metres along z
  float cell = 0.15f;     // metres per storyboard pixel (glyph centres at least 5 px apart)
  double density = 14.0;  // the sample storyboard's glyphs per 1000 px²
  uint64_t seed = 1;
  crowd::AvoidanceParams avoidance;
};

// About 500 agents in the default 60 × 15 m corridor (ten times as many in a 600 m one).
// Throws Error for sizes that make no storyboard (fewer than 20 × 20 pixels) or too many pixels.
SceneSetup corridorScene(const CorridorDescription& description);

}  // namespace throng::scene
