#pragma once
// Levels of detail of the garment for distant capes. Vertices are clustered on grids of growing
// cell size (1, 2, 4 and 16 mean edge lengths) over the mean shape (each level's representatives
// chosen among the finer level's), and reordered coarse-first, so level L is the prefix order[0 …
// vertices_L): decoding a state at level L computes only that prefix (with the first bases_L
// bases), and any finer decode holds it too. Triangles of level L join representatives (degenerate
// and repeated ones dropped). Level L keeps max(min(b, 32 >> L), ⌈b / 2^L⌉) bases (the first ones
// carry the most motion).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "secondary/cloth_database.h"
#include "shaders/cloth_types.h"

namespace throng::secondary {

constexpr uint32_t kClothLevels = gpu_types::kClothLevelCount;

struct ClothLod {
  uint32_t vertexCount = 0;                      // V (level 0)
  std::vector<uint32_t> order;                   // position k → original vertex
  std::vector<uint32_t> levelVertices;           // per level: prefix length
  std::vector<uint32_t> levelBases;              // per level: bases decoded
  std::vector<uint32_t> indices;                 // every level's triangles, in positions
  std::vector<uint32_t> firstIndex, indexCount;  // per level
  // remap[d · V + k]: position of the level-d representative of position k (to draw a finer level
  // from a state decoded coarser).
  std::vector<uint32_t> remap;
  // Bounding sphere of every state in character space (for culling): the mean shape's, grown by
  // the largest displacement the coefficients allow (max_s Σ_i |c'_si| max |B'_i| · √3).
  glm::vec3 center{0.0f};
  float radius = 0.0f;
  float shapeRadius = 0.0f;  // the mean shape's alone (for the on-screen size that picks a level)
};

ClothLod buildClothLod(const ClothDatabase& db);

}  // namespace throng::secondary
