#pragma once
// Garment meshes for the cloth simulator: a cape hung from the neck and shoulders down the
// back, and a plain square for tests.
#include <cstdint>
#include <vector>

#include "secondary/offline/body_capsules.h"
#include "secondary/secondary_types.h"

namespace throng::secondary {

struct CapeOptions {
  uint32_t columns = 32;   // vertices across
  uint32_t rows = 48;      // vertices down (32 × 48 = 1,536 vertices)
  float topWidth = 0.36f;  // metres across the top row
  float flare = 1.4f;      // bottom width / top width
  float length = 0.85f;    // metres from the top row to the hem
  // Gap kept between the rest shape and the body capsules (the plane of the cape is tilted
  // back just enough; the top row moves back when even the steepest tilt does not clear).
  float clearance = 0.03f;
  uint32_t node = 0;  // the primary node whose pose the rest shape is built at
  std::vector<BoneCapsule> capsules = defaultBodyCapsules();
};

// A trapezoid grid (rows × columns, two triangles per cell) in character space at the node's
// pose: top row centred behind the neck/shoulder joints, the rest hanging down the back. The
// top row is pinned, each vertex to the nearest neck/shoulder joint (neckShoulderJoints), with
// pinOffsets in that joint's frame. Throws Error on a skeleton without such joints or options
// out of range.
ClothMesh makeCape(const PrimaryGraph& graph, const CapeOptions& options = {});

// An n × n grid of `size` metres lying flat at y = 0 (x in [−size/2, size/2], z in [0, size]),
// the row at z = 0 pinned to joint 0 with pinOffsets = rest positions: with joint 0 at the
// origin (identity rotation) it hangs from that edge.
ClothMesh makeSquareCloth(uint32_t n, float size);

// Rows × columns grid triangles (two per cell, diagonals alternating), shared by both meshes.
std::vector<uint32_t> gridTriangles(uint32_t rows, uint32_t columns);

}  // namespace throng::secondary
