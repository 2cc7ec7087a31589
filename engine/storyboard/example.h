#pragma once
// Random valid storyboards for tests and demos. Agents come in spatial groups (each group owns
// the region nearest its seed point) that share a main heading and state, as a person drawing
// a plaza would: tourists strolling one way, commuters hurrying another.
#include <cstdint>
#include <vector>

#include "storyboard/glyph.h"

namespace throng::storyboard {

struct ExampleOptions {
  int width = 90, height = 90;
  uint64_t seed = 1;
  double density = 10.0;  // target agents per 1000 px²
  int groups = 4;
  int spacing = 5;        // minimum Chebyshev distance between centres (>= 4 keeps cells apart)
};

// Glyphs in reading order with groups numbered by first appearance (canonical), so they
// round-trip through encodeStoryboard/decodeStoryboard unchanged.
std::vector<Glyph> generateExampleGlyphs(const ExampleOptions& options);

}  // namespace throng::storyboard
