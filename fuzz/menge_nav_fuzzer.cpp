// Menge's text resources (the first byte picks: even a .nav navigation mesh, odd a road map)
// → vertices, edges, obstacles, node polygons and adjacency; road-map vertices, edges, degrees.
#include "fuzz_support.h"
#include "menge/menge.h"

using namespace throng;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const std::string_view text = fuzz::asText(data + 1, size - 1);
  fuzz::expectParseOrError([&] {
    if (data[0] % 2 == 0) {
      (void)menge::parseNavMesh(text, "fuzz.nav");
    } else {
      (void)menge::parseRoadMap(text, "fuzz_map.txt");
    }
  });
  return 0;
}
