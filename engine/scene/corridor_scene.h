#pragma once
// The storyboard paper's own experiment as a scene: a subway corridor (two long walls, both
// ends open) filled with a storyboard quilted to its size — people walking both ways, hurrying,
// standing and talking in groups. Walkers follow the path vectors of real tracked people
// (docs/design.md, "Storyboard crowds"): each walker takes one person's per-second vectors, turned
// so that person's overall direction points along the corridor to the end the walker's glyph faces,
// scaled to its clip pair's speeds, repeated until it is past that end, folded at the walls (the
// lateral drift is kept, reflected back into the corridor) and held at a spot past the end, inside
// the walls. Avoidance of each other and of the walls does the rest. Without the tracked set
// walkers head for that end by goals instead. The sample storyboard is made in code
// (storyboard/example.h), so the scene needs no file of its own.
#include <cstdint>
#include <string>
#include <vector>

#include "core/file_io.h"
#include "scene/scene.h"

namespace throng::scene {

// The tracked set walkers take their path vectors from unless told otherwise: UCY's zara01
// sidewalk (93 % of its people walk along one axis, half each way), inside the shared data
// folder beside the repository (core/file_io.h, sharedDataPath).
inline constexpr const char* kCorridorTrajectories = "trajectories/sgan_format/crowds_zara01.txt";

struct CorridorDescription {
  float length = 60.0f;   // metres along x, centred at the origin
  float width = 15.0f;    // metres along z
  float cell = 0.15f;     // metres per storyboard pixel (glyph centres at least 5 px apart)
  double density = 14.0;  // the sample storyboard's glyphs per 1000 px²
  uint64_t seed = 1;
  crowd::AvoidanceParams avoidance;
  // Path vectors of these tracked people (crowd/trajectories.h); empty or absent: goals, with a
  // message saying so.
  std::string trajectories = sharedDataPath(kCorridorTrajectories).string();
};

// About 500 agents in the default 60 × 15 m corridor (ten times as many in a 600 m one).
// Throws Error for sizes that make no storyboard (fewer than 20 × 20 pixels) or too many pixels,
// and for a tracked set that is present but unreadable.
SceneSetup corridorScene(const CorridorDescription& description);

// Per agent of a corridor scene: +1 walks to the +x end, −1 to the −x end, 0 stands (talkers).
std::vector<int> corridorDirections(const SceneSetup& corridor);

// Walkers stop on spots drawn uniformly between half a metre and `corridorStopDepth` past the
// end they walk to, so that once everyone is there they stand about kCorridorArrivalDensity
// people per m² (a deeper area for the longer corridor's crowd). The walls reach
// `corridorWallReach` past each end, around those spots.
inline constexpr float kCorridorArrivalDensity = 1.0f;  // people per m²
float corridorStopDepth(size_t walkersToEnd, float width);
float corridorWallReach(size_t walkersToEnd, float width);

}  // namespace throng::scene
