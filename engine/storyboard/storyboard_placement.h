#pragma once
// Storyboard → crowd (issue 6, part 3). Each decoded glyph becomes an agent:
//   * position: the glyph's centre pixel × cellSize metres, the storyboard centred on the
//     origin, image x → world +x and image y (down) → world +z (seen from above with −z up the
//     screen the picture is not mirrored), plus a uniform jitter of ±jitter metres;
//   * heading: the glyph's (Top faces −z, Down +z, Right +x, Left −x; diagonals between);
//   * state → a speed range (strolling, hurried), a speed drawn in it, and w from the clip
//     pair's root speeds;
//   * action → Crowd::clipSet (walk 0, run 1, talk 2, jump 3): the agents are ordered by clip
//     set (stable: within a set in glyph order), so each set is one contiguous range that one
//     motion pair's synthesis can take; `glyph` maps an agent back to its glyph;
//   * group → tint index (a side array, so Crowd stays what the synthesis passes read).
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "crowd/crowd.h"
#include "crowd/path_vectors.h"
#include "storyboard/codec.h"

namespace throng::storyboard {

struct RootSpeeds {
  float slow = 0.0f, fast = 0.0f;  // m/s
};

struct PlacementOptions {
  float cellSize = 0.5f;  // metres per storyboard pixel
  float jitter = 0.1f;    // ± metres added to x and z
  uint64_t seed = 1;
  // Speed ranges per State (m/s): strolling people in the ETH/UCY sets walk 0.4–1.2 m/s.
  std::array<crowd::SpeedRange, kStateCount> speeds = {{{0.4f, 1.2f}, {1.2f, 2.2f}}};
  float slowSpeed = 0.0f;  // root speeds of the clip pair (anim::clipRootSpeed); w = 0 when equal
  float fastSpeed = 0.0f;
  // Per action, when its clip pair differs (walk, run, talk, jump): root speeds of that pair.
  // A pair that does not travel (slow = fast = 0, e.g. talk) gets a random w: how animated.
  std::optional<std::array<RootSpeeds, kActionCount>> actionSpeeds;
  float minScale = 0.92f, maxScale = 1.08f;
};

struct Placement {
  crowd::Crowd crowd;           // ordered by clip set
  std::vector<uint32_t> glyph;  // per agent: its glyph in the storyboard
  std::array<uint32_t, kActionCount + 1>
      setBegin{};                             // clip set k: agents [setBegin[k], setBegin[k + 1])
  std::vector<uint32_t> tint;                 // per agent: group number
  std::vector<crowd::SpeedRange> speedRange;  // per agent: its state's range
  std::vector<float> speed;                   // per agent: the desired speed drawn in it
};

// World heading (radians, 0 faces +z, +π/2 faces +x) of a glyph heading.
float headingAngle(Heading heading);
uint32_t clipSetOf(Action action);

// Throws Error for a non-positive cell size, negative jitter or an empty/unordered range.
Placement placeStoryboard(const Storyboard& storyboard, const PlacementOptions& options);

}  // namespace throng::storyboard
