#pragma once
// The CPU twin of shaders/cloth_splat.comp: far capes rasterized into a visibility buffer of
// (depth bits << 32 | colour) per pixel, nearest kept (render::kEmptyPixel where nothing is).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "secondary/cloth_decoder.h"
#include "secondary/cloth_view.h"

namespace throng::secondary {

// A cape's colour (shaders/cloth_common.glsl clothTint and clothLevelTint).
glm::vec3 clothTint(uint32_t character);
glm::vec3 clothLevelTint(uint32_t level);

struct SplatInputs {
  const gpu_types::ClothView* view =
      nullptr;  // viewport = the buffer's size; viewport.w: tint by level
  const PlaybackTables* tables = nullptr;
  const ClothLod* lod = nullptr;
  const DecodedBases* decoded = nullptr;  // dequantize(db) (original vertex order)
  std::span<const uint32_t> stateLevel;   // the level each state was decoded at
  std::span<const ClothCharacter> characters;
  std::span<const glm::vec4> placement, motion;
};

// Splats `splatted` (characters at kClothSplatLevel) into `visibility` (width × height).
void splatCapesCpu(const SplatInputs& in, std::span<const uint32_t> splatted,
                   std::span<uint64_t> visibility);

}  // namespace throng::secondary
