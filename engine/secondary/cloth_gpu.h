#pragma once
// GPU residency of cloth playback: the database (uploaded once: dequantized bases and
// coefficients in the LOD's coarse-first vertex order, the graph tables, the level meshes), the
// per-crowd buffers the passes share, and the compiled programs.
#include <cstdint>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/graphics_pipeline.h"
#include "gpu/program.h"
#include "secondary/cloth_database.h"
#include "secondary/cloth_decoder.h"
#include "secondary/cloth_lod.h"
#include "secondary/cloth_playback.h"

namespace throng::secondary {

// The graph tables in one uint array: word t (< kClothGraphTables) is the offset of table t
// (order of the kTable* constants in shaders/cloth_common.glsl), then the tables.
constexpr uint32_t kClothGraphTables = 9;
std::vector<uint32_t> clothGraphTable(const ClothDatabase& db, const PlaybackTables& t);

struct ClothGpuData {
  uint32_t vertexCount = 0, basisCount = 0, stateCount = 0, bucketCount = 0;
  uint32_t rowVectors = 0;  // vec4s per basis row block: ceil(3V / 4)
  float bucketWidth = 0.0f;
  PlaybackTables tables;
  ClothLod lod;
  gpu::Buffer mean;          // rowVectors vec4: the 3V rows in coarse-first order, zero padded
  gpu::Buffer bases;         // b × rowVectors vec4, same order
  gpu::Buffer coefficients;  // S × b floats
  gpu::Buffer levels;        // ClothLevel per level
  gpu::Buffer graph;         // clothGraphTable
  gpu::Buffer indices;       // every level's triangles (index buffer)
  gpu::Buffer remap;         // ClothLod::remap
  // The far-cape splat, specialized for the splat level's mesh; empty when the device has no
  // 64-bit buffer atomics or the level is too large (kClothSplatMaxVertices, ...MaxTriangles).
  gpu::ComputeProgram splat;
};
ClothGpuData uploadCloth(const gpu::Context& context, const ClothDatabase& db);
// Whether far capes are splatted (else drawn as triangles).
inline bool clothSplattable(const ClothGpuData& cloth) {
  return static_cast<bool>(cloth.splat.pipeline());
}
// The mean and bases permuted to the LOD order (what uploadCloth sends; for twins and tests).
DecodedBases permutedBases(const DecodedBases& decoded, const ClothLod& lod);
// Pool vertices a state decoded at `level` takes (a multiple of 4: whole vec4 rows).
inline uint32_t slotVertices(const ClothLod& lod, uint32_t level) {
  return (lod.levelVertices[level] + 3u) & ~3u;
}

// The per-crowd buffers of the passes. The pool holds the decoded states: a coarse region with
// room for every used state at the coarsest level, then a budget for finer levels (states that do
// not fit it are decoded at the coarsest level and drawn through the remap).
struct ClothCrowdBuffers {
  uint32_t characterCount = 0;
  uint32_t maxUsedStates = 0;     // min(states, 2 × characters): a state and a blend source each
  uint32_t reservedVertices = 0;  // coarse region
  uint32_t fineBudget = 0;        // vertices of the fine region
  gpu::Buffer characters;         // ClothCharacter per character
  gpu::Buffer counters;           // ClothCounters (host-visible: statistics)
  gpu::Buffer stateLevel;         // per state: finest level needed this frame, kClothNone unused
  gpu::Buffer usedStates;         // the used states, in the order the mark pass found them
  gpu::Buffer levelLists;         // levels × maxUsedStates: the states decoded at each level
  gpu::Buffer slots;              // per state: uvec2 (pool vertex, decoded level)
  gpu::Buffer pool;               // floats, 3 per decoded vertex
  gpu::Buffer draws;         // VkDrawIndexedIndirectCommand per level (host-visible: statistics)
  gpu::Buffer drawList;      // levels × characters
  gpu::Buffer dispatchArgs;  // VkDispatchIndirectCommand: classify, decode per level, splat
};
// `fineBudgetBytes` bounds the fine region (default 48 MB); the whole pool must fit one storage
// binding (Error otherwise).
ClothCrowdBuffers makeClothCrowdBuffers(const gpu::Context& context, const ClothGpuData& cloth,
                                        uint32_t characterCount,
                                        uint64_t fineBudgetBytes = 48ull << 20);

struct ClothStats {
  uint32_t usedStates = 0;
  uint32_t demoted = 0;
  uint32_t fineVertices = 0;
  uint32_t capes[kClothLevels] = {};  // characters drawn (or splatted) per level
};
// Reads the counters of the last completed frame.
ClothStats readClothStats(const ClothCrowdBuffers& buffers);

struct ClothPrograms {
  gpu::ComputeProgram advance;
  gpu::ComputeProgram mark;
  gpu::ComputeProgram args;
  gpu::ComputeProgram classify;
  gpu::ComputeProgram decode;
  gpu::GraphicsProgram draw;
  ClothPrograms(const gpu::Context& context, VkFormat colorFormat, VkFormat depthFormat);
};

}  // namespace throng::secondary
