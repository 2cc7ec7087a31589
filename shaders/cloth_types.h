// Structs of the cloth playback passes (engine/secondary/cloth_gpu*.h), shared by C++ and GLSL
// like shared_types.h. C++ includes this file through secondary/cloth_gpu_types.h (static_asserts).
#ifndef THRONG_CLOTH_TYPES_H
#define THRONG_CLOTH_TYPES_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace throng::gpu_types {
using vec4 = glm::vec4;
using uint = uint32_t;
using mat4 = glm::mat4;
#endif

// One character's cloth traversal: its state, the primary node it showed, and the merge blend
// (blendSource shown with weight countdown / (kMergeBlendFrames + 1)). 0xFFFFFFFF: none yet.
struct ClothCharacter {
  uint state;
  uint node;
  uint blendSource;
  uint countdown;
};

const uint kClothNone = 0xFFFFFFFFu;
const uint kClothLevelCount = 4u;      // garment LOD levels (cloth_lod.h)
const uint kClothSplatLevel = 3u;      // the coarsest level: splatted by a compute pass when it can
const uint kClothSharedLevel = 2u;     // from this level on, a cape shows its node's first state
const uint kClothMaxGroups = 65535u;
const uint kClothDecodeGroup = 8u;     // decode workgroup size (cloth_decode.comp)

// Push constants of the advance pass.
struct ClothAdvancePush {
  uint characterCount;
  uint bucketCount;
  float bucketWidth;
  uint maxWalkSteps;
  uint blendFrames;
  uint pad0;
  uint pad1;
  uint pad2;
};

// Per-level constants of the garment LOD.
struct ClothLevel {
  uint vertices;    // decoded prefix of the coarse-first vertex order
  uint bases;       // bases decoded
  uint firstIndex;  // the level's triangles in the index buffer
  uint indexCount;
};

// The frame's camera for the mark pass (culling, level choice), the draw and the splat (a uniform
// buffer).
struct ClothView {
  mat4 viewProjection;
  vec4 planes[6];   // frustum: dot(plane.xyz, p) + plane.w >= 0 inside
  vec4 eye;         // xyz: camera position, w: focal length (px)
  vec4 lod;         // smallest on-screen diameter (px) of level 0, 1, 2 (x, y, z); w: 1 = LOD on
  vec4 bounds;      // xyz: bounding-sphere centre in character space, w: its radius (culling)
  vec4 light;       // xyz: towards the light, w: the mean shape's radius (on-screen size)
  vec4 viewport;    // width, height (px); z: 1 = the splat level is splatted; w: 1 = tint by level
};

// The mark pass counts used states, the classify pass allocates pool space from fineCursor and
// lists the states per decoded level.
struct ClothCounters {
  uint usedStates;
  uint fineCursor;
  uint demoted;     // states decoded coarser than wanted because the fine pool was full
  uint pad0;
  uint levelStates[4];  // states decoded at each level (kClothLevelCount)
};

struct ClothMarkPush {
  uint characterCount;
  uint maxUsedStates;
  uint pad0;
  uint pad1;
};

// The args pass: mode 0 sizes the classify pass; mode 1 the decode pass of each level (at
// dispatchArgs[3 + 3·level]) and the splat (at dispatchArgs[3 + 3·kClothLevelCount]).
struct ClothArgsPush {
  uint mode;
  uint maxUsedStates;
  uint characterCount;
  uint pad0;
};

struct ClothClassifyPush {
  uint maxUsedStates;
  uint fineBudget;        // vertices in the pool's fine region
  uint reservedVertices;  // the coarse region: maxUsedStates × slot size of the coarsest level
  uint pad0;
};

// Bases, mean and pool are vec4 rows (row r = 3·vertex + axis of the coarse-first order); pool
// slots start at multiples of 4 vertices, so a slot's rows are whole vec4s.
struct ClothDecodePush {
  uint rowVectors;        // vec4s per basis: ceil(3V / 4)
  uint basisCount;        // coefficient stride per state
  uint level;             // the states decoded by this dispatch
  uint maxUsedStates;     // stride of the per-level state lists
};
const uint kClothDecodeRows = 8u;     // vec4 rows a decode round shares (at most; padding of the bases)
const uint kClothSplatMaxVertices = 32u;   // the splat level is splatted only up to this size
const uint kClothSplatMaxTriangles = 16u;

struct ClothSplatPush {
  uint characterCount;    // the splat level's list starts at kClothSplatLevel × characterCount
  uint pad0;
  uint pad1;
  uint pad2;
};

struct ClothDrawPush {
  uint characterCount;    // instance i draws drawList[i] at level i / characterCount
  uint vertexCount;       // V: remap stride
  uint blendFrames;
  uint flags;             // kClothDrawTint: colour by level
};

const uint kClothDrawTint = 1u;

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
