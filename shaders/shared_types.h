// Structs shared by C++ and GLSL: one definition, sizes checked on the C++ side.
// GLSL includes this file (GL_GOOGLE_include_directive); C++ includes it through
// synth/gpu_types.h, which adds the static_asserts.
#ifndef THRONG_SHARED_TYPES_H
#define THRONG_SHARED_TYPES_H

#ifdef __cplusplus
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
namespace throng::gpu_types {
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
using glm::dot;
using std::sqrt;
using uint = uint32_t;
using mat4 = glm::mat4;
#define THRONG_STRUCT(name) struct name
#define THRONG_INLINE inline
#else
#define THRONG_STRUCT(name) struct name
#define THRONG_INLINE
#endif

// Per-character state lives in two vec4 arrays (structure of arrays):
//   placement[i] = (x, y, z, heading)   heading in radians about +y, 0 faces +z
//   motion[i]    = (phase, w, wTarget, scale)
// The motion vector's components are read and written through the functions below, in GLSL and
// C++ alike, never as .x/.y/.z/.w. Functions rather than #defined component names, because a
// macro such as `speedWeight` would rewrite every identifier of that name in both languages;
// the setters return the changed vector since GLSL has no references (m = withSpeedWeight(m, w)).
THRONG_INLINE float cyclePhase(vec4 m) { return m.x; }         // in [0, 1): where in the clip cycle
THRONG_INLINE float speedWeight(vec4 m) { return m.y; }        // w: 0 the slow clip, 1 the fast
THRONG_INLINE float targetSpeedWeight(vec4 m) { return m.z; }  // wTarget: w at the next cycle end
THRONG_INLINE float characterScale(vec4 m) { return m.w; }     // body size, 1: the clips' own
THRONG_INLINE vec4 makeMotion(float phase, float w, float wTarget, float scale) {
  return vec4(phase, w, wTarget, scale);
}
THRONG_INLINE vec4 withCyclePhase(vec4 m, float phase) {
  m.x = phase;
  return m;
}
THRONG_INLINE vec4 withSpeedWeight(vec4 m, float w) {
  m.y = w;
  return m;
}
THRONG_INLINE vec4 withTargetSpeedWeight(vec4 m, float wTarget) {
  m.z = wTarget;
  return m;
}

// One joint's draw matrix A = M·O·F as three rows of a 3x4 affine matrix (row r = (R[r], t[r])):
// the unit mesh (a sphere of radius 1 around (0, 0.5, 0), squashed to y in [0, 1]) placed as the
// joint's bone. What the readers of the pose draw and test; the pose itself is stored as points.
THRONG_STRUCT(JointMatrix) {
  vec4 row0;
  vec4 row1;
  vec4 row2;
};

// One joint of a synthesized pose as the pose pass writes it (and the motion cache stores it):
// xyz the joint's position, w the radius its bone is drawn with (0: not drawn). The bone runs
// from the parent's position to the joint's; the root's is a sphere of that radius around it.
// Sixteen bytes where a draw matrix takes 48: on lavapipe every store is a loop over the lanes,
// and the pose pass is bound by its stores. Readers rebuild the matrix (boneMatrix).
THRONG_STRUCT(JointPoint) {
  vec4 positionRadius;
};

// The point t of the way along joint j's bone: A·(0, t, 0, 1) of its draw matrix. `parent` is the
// parent's point (ignored for the root, whose bone is vertical, 2·radius long, centred on it).
THRONG_INLINE vec3 bonePoint(vec4 parent, vec4 joint, bool root, float t) {
  if (root) return vec3(joint.x, joint.y + (2.0f * t - 1.0f) * joint.w, joint.z);
  return vec3(parent.x, parent.y, parent.z) + t * (vec3(joint.x, joint.y, joint.z) - vec3(parent.x, parent.y, parent.z));
}

// Joint j's draw matrix from its point and its parent's. The bone's ellipsoid is round about the
// bone (its two cross axes are both the radius long), so any two axes perpendicular to the bone
// draw it alike; these are the branchless orthonormal basis of Duff et al. (2017).
THRONG_INLINE JointMatrix boneMatrix(vec4 parent, vec4 joint, bool root) {
  float radius = joint.w;
  vec3 start = bonePoint(parent, joint, root, 0.0f);
  vec3 axis = bonePoint(parent, joint, root, 1.0f) - start;
  float boneLength = sqrt(dot(axis, axis));
  vec3 n = boneLength > 1e-12f ? axis * (1.0f / boneLength) : vec3(0.0f, 1.0f, 0.0f);
  float sign = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (sign + n.z);
  float b = n.x * n.y * a;
  vec3 side = radius * vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  vec3 other = radius * vec3(b, sign + n.y * n.y * a, -n.y);
  JointMatrix m;
  m.row0 = vec4(side.x, axis.x, other.x, start.x);
  m.row1 = vec4(side.y, axis.y, other.y, start.y);
  m.row2 = vec4(side.z, axis.z, other.z, start.z);
  return m;
}

// The display's gamma, x^(1/2.2), for x clamped to [0, 1] (a colour channel packed to 8 bits
// clamps there anyway): a quartic in √x fitted for the least largest error (Lawson's algorithm),
// within 0.0017 of the power, under half a level of 255. pow is a logarithm and an exponential,
// each a long polynomial on lavapipe, for every channel of every shaded pixel; this is one square
// root and four multiply-adds.
THRONG_INLINE float gammaEncode(float x) {
  float t = sqrt(x > 0.0f ? (x < 1.0f ? x : 1.0f) : 0.0f);
  return 0.0016943700f + t * (1.2867752f + t * (-0.81337190f + t * (0.90519303f + t * -0.38198549f)));
}

// Push constants of the root-motion pass (the paper's eq. 10, docs/design.md).
THRONG_STRUCT(RootMotionPush) {
  uint characterCount;
  uint slowFrames;
  uint fastFrames;
  uint firstCharacter;    // the group [firstCharacter, firstCharacter + characterCount)
  float dt;
  float slowDuration;     // seconds per cycle
  float fastDuration;
  float cacheBucketWidth; // > 0: also flag each character's motion-cache bucket as requested
  vec4 slowCycleTravel;   // xyz: root displacement over one slow cycle
  vec4 fastCycleTravel;
  uint cacheBucketCount;  //   (the cache's lookup step, done here: no pass of its own)
  // Scheduled (update_rate.h): how far a character may walk, in its standing heights, before its
  // chunk's next move; the body sphere that decides whether it may be drawn grows by it.
  float reachPerHeight;
  uint pad1;
  uint pad2;
};

// Push constants of root_motion_prep.comp, the pass before root motion on the steps that steer
// or draw new target speeds: what it changes (the heading, the target speed weight) is what
// root motion then reads, as anim::stepCharacter does in one function.
THRONG_STRUCT(RootMotionPrepPush) {
  uint characterCount;
  uint firstCharacter;    // the group [firstCharacter, firstCharacter + characterCount)
  uint steering;          // 0: keep heading, 1: run around a circle centred at the origin
  uint retargetEpoch;     // > 0: every character draws a new target speed weight this step
  uint seed;
  float minSpeedWeight;   // range of the new targets
  float maxSpeedWeight;
  float bucketWidth;      // > 0: new target speeds are quantized to motion-cache buckets
};

// A crowd of several clip sets synthesized in one dispatch per pass (synth/group_passes.h):
// each group's clips and cache as the merged root-motion and cache-classify passes read them,
// every group in one uniform table. A character's group is the last one whose firstCharacter
// it has reached.
const uint kSynthMaxGroups = 4u;
THRONG_STRUCT(SynthGroupInfo) {
  uint firstCharacter;
  uint slowFrames;
  uint fastFrames;
  uint pad1;              // (the travel vectors start at byte 32)
  float slowDuration;
  float fastDuration;
  uint slowRootBase;      // the clips' root rows (one vec4 per frame) in the shared root-row buffer
  uint fastRootBase;
  vec4 slowCycleTravel;
  vec4 fastCycleTravel;
  uint bucketBase;        // the group cache's first bucket in the shared requested and bucketSlot
  uint pad0;
  uint cacheRowCount;
  uint cacheDataBase;
};
THRONG_STRUCT(SynthGroupTable) {
  uvec4 counts;           // x: groups
  SynthGroupInfo groups[kSynthMaxGroups];
};

// Push constants of the pose pass (blend + hierarchy + A = J·M).
THRONG_STRUCT(PosePush) {
  uint characterCount;
  uint jointCount;
  uint slowFrames;
  uint fastFrames;
  uint firstCharacter;    // dispatch in chunks: output index = character - firstCharacter
  uint fromList;          // 1: invocation k poses characterList[listBase + k], k < listCounts[countIndex]
  uint listBase;
  uint countIndex;
  uint cacheRowCount;     // poses per motion-cache entry (not read by the pose passes)
  float bucketWidth;      // speed-weight bucket width of the cache
  uint flags;             // kPoseUseMasks: skip the joints a character's LOD mask leaves out
  uint pad1;
};

const uint kPoseUseMasks = 1u;

// The motion cache's counters and FIFO state (the paper's §3.4, docs/design.md), kept on the GPU.
THRONG_STRUCT(CacheCounters) {
  uint hits;              // requested buckets found resident (one lookup per bucket per frame)
  uint misses;            // requested buckets synthesized and inserted
  uint evictions;         // entries dropped, oldest first, to make room
  uint entries;           // resident entries
  uint head;              // next slot to fill (the oldest entry once full)
  uint capacity;          // entries that fit the byte budget
  uint bucketCount;
  uint pad0;
};

// Push constants of the cache passes.
THRONG_STRUCT(CachePush) {
  uint characterCount;    // lookup: the group's characters; classify: this chunk's
  uint rowCount;          // poses per entry, at phases r / rowCount (synth::cacheRowCount)
  uint slotCount;         // capacity (fill pass: slots × rows invocations)
  float bucketWidth;
  uint firstCharacter;    // lookup: the group's first character; classify: the chunk's
  uint chunk;             // classify: the chunk's uncached count is at listCounts[chunk]
  uint dataBase;          // fill, classify: the cache's first point in the (shared) data buffer
  uint jointCount;        // classify: cached pose entries are jointCount points apart
  uint slowFrames;        // fill: rows of the slow and fast motion textures
  uint fastFrames;
  uint farBodies;         // fill: also each pose's FarBodyPose (the LOD on: far bodies drawn)
  uint pad1;
};

// Push constants of the cache classify pass over every group (cache_classify_groups.comp).
THRONG_STRUCT(ClassifyGroupsPush) {
  uint characterCount;    // the dispatch's characters, from firstCharacter
  uint firstCharacter;
  uint chunkSize;         // characters per pose chunk; chunks are numbered across groups, each
  uint bucketCount;       //   group's from its first character; buckets per cache
  float bucketWidth;
  uint jointCount;
  uint pad0;
  uint pad1;
  uvec4 firstChunk;       // per group: its first chunk's number
};

// poseSource[character]: where the character's joint points come from this frame. A cached
// character's is the index of its first point in the cache data (the renderer places them,
// M · p, itself, so synthesis writes nothing per joint for it); the others' is
// kPoseInJoints: their points were synthesized into the joints buffer.
const uint kPoseInJoints = 0xFFFFFFFFu;

// Per-frame camera and light for the joint and ground draws (a uniform buffer).
THRONG_STRUCT(FrameUniforms) {
  mat4 viewProjection;
  vec4 eye;               // xyz: camera position; w: ground half-extent
  vec4 lightDirection;    // xyz: towards the light, normalized
  vec4 rayRight;          // camera right · tan(fovX/2): ray = forward + ndc.x·right + ndc.y·down
  vec4 rayDown;           // camera down · tan(fovY/2) (Vulkan NDC y points down)
  vec4 rayForward;        // camera forward
  vec4 viewport;          // width, height, focal length in pixels, 0
  // Byte j: joint j's parent (kNoParent for the root), so a joint's bone is found from its point
  // and its parent's (JointPoint).
  uvec4 jointParents[4];
};
const uint kNoParent = 255u;

// Push constants of one joint draw (a chunk of characters).
THRONG_STRUCT(DrawPush) {
  uint jointCount;
  uint firstCharacter;    // vertex index + firstCharacter·jointCount is the global joint
  uint flags;             // kDraw* bits below
  uint listBase;
  uint boneLo;            // bit j: joint j's bone is drawn (a placement's is not), joints 0..31
  uint boneHi;            // joints 32..63
};

const uint kDrawFromList = 1u;   // vertex i draws joint nearList[listBase + i]
const uint kDrawUseMasks = 2u;   // skip joints the character's LOD mask leaves out
const uint kDrawTintLevel = 4u;  // colour characters by LOD level (paper Fig. 8)
const uint kDrawCachedPoses = 8u;  // compose cached characters' joints from poseSource + cache data
const uint kDrawGroupTint = 16u;   // colour characters by their group (binding 10: a uint per character)
const uint kDrawLodLevels = 32u;   // with kDrawUseMasks: per-level drawn joints and long bones (binding 11)

// Push constants of the joint splat (compute path for small joints). Joints too wide to splat
// are appended to nearList[listBase …] and counted in draws[chunk].vertexCount, an indirect
// draw of exactly those joints.
THRONG_STRUCT(SplatPush) {
  uint jointCount;        // joints per character
  uint firstCharacter;
  uint jointTotal;        // joints in this chunk
  float maxPixels;        // sprites wider than this are left to the graphics pipeline
  uint chunk;
  uint listBase;
  uint flags;             // kDrawUseMasks, kDrawTintLevel
  uint pad1;
  uint boneLo;            // as DrawPush
  uint boneHi;
};

#undef THRONG_INLINE

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
