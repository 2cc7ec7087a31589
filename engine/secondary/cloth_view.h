#pragma once
// The camera as the cloth passes see it (culling and the garment level from the cape's size on
// screen), and the CPU twin of the mark pass.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "render/camera.h"
#include "secondary/cloth_gpu_types.h"
#include "secondary/cloth_lod.h"
#include "secondary/cloth_playback.h"

namespace throng::secondary {

// Capes at least level0Pixels across on screen take level 0 (all vertices and bases), at least
// level1Pixels level 1, at least level2Pixels level 2, smaller ones level 3. From level 2 on a
// cape shows the first state of its primary node (the secondary variation is invisible there, and
// far capes then share at most one decoded state per node). Level 3 is splatted by a compute pass
// into the joint renderer's visibility buffer when the device can (64-bit atomics).
struct ClothLodSettings {
  bool enabled = true;
  float level0Pixels = 160.0f;
  float level1Pixels = 64.0f;
  float level2Pixels = 24.0f;
};

gpu_types::ClothView makeClothView(const render::Camera& camera, uint32_t width, uint32_t height,
                                   const ClothLod& lod, const ClothLodSettings& settings,
                                   bool splat = false);

// The level of a character's cape (0 finest), or kClothNone when it is outside the view.
uint32_t clothLevel(const gpu_types::ClothView& view, glm::vec4 placement, float scale);

// The state a character's cape shows at `level` (its own, or its node's first from
// kClothSharedLevel on), and whether it blends from its blend source there.
uint32_t shownState(const PlaybackTables& t, const ClothCharacter& c, uint32_t level);
bool showsBlend(const ClothCharacter& c, uint32_t level);

// What the mark pass computes, order aside: per state the finest level a visible character needs
// (kClothNone: unused), and per level the characters drawn at it (ascending).
struct ClothMarks {
  std::vector<uint32_t> stateLevel;
  std::array<std::vector<uint32_t>, kClothLevels> drawLists;
  uint32_t usedStates = 0;
};
ClothMarks markCharacters(const gpu_types::ClothView& view, const PlaybackTables& tables,
                          uint32_t stateCount, std::span<const ClothCharacter> characters,
                          std::span<const glm::vec4> placement, std::span<const glm::vec4> motion);

// A character's cape vertex in world space: character space → root (x, y, z, heading, scale).
glm::vec3 placeClothVertex(glm::vec4 placement, float scale, glm::vec3 p);

}  // namespace throng::secondary
