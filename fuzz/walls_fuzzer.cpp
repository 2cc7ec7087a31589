// Walls text (docs/formats.md, "Walls") → segments → the binning and a few constrained moves.
#include "crowd/obstacles.h"
#include "crowd/walls_file.h"
#include "fuzz_support.h"

using namespace throng;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  fuzz::expectParseOrError([&] {
    const crowd::Obstacles walls = crowd::parseWalls(fuzz::asText(data, size), "fuzz.txt");
    // Large cells and a small budget keep each input fast; over it is an Error, as for users.
    const crowd::WallGrid grid = crowd::binObstacles(walls, 10.0f, 10.0f, size_t(1) << 20);
    for (const crowd::Segment& s : walls.segments) {
      crowd::constrainMove(grid, s.a + glm::vec2(0.5f, 0.5f), s.b - glm::vec2(0.5f, 0.5f), 0.3f);
      if (&s - walls.segments.data() >= 16) break;
    }
  });
  return 0;
}
