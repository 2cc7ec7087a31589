// Structs of the pixel-coverage pass (the paper's eqs. 1–9, docs/design.md), shared by C++ and GLSL like
// shared_types.h; C++ includes this file through synth/coverage.h, which checks the sizes.
#ifndef THRONG_COVERAGE_TYPES_H
#define THRONG_COVERAGE_TYPES_H

#include "shared_types.h"

#ifdef __cplusplus
namespace throng::gpu_types {
using uvec4 = glm::uvec4;
#endif

// The five bounding spheres, in this order everywhere (state's part bits, areas).
const uint kPartLeftArm = 0u;
const uint kPartRightArm = 1u;
const uint kPartTorso = 2u;
const uint kPartLeftLeg = 3u;
const uint kPartRightLeg = 4u;
const uint kCoveragePartCount = 5u;

// CoveragePush.flags
const uint kCoverageReadJoints = 1u;  // sphere centres from the joint points (else estimated)
const uint kCoverageWriteAreas = 2u;  // measure the five part spheres: areas and state bits

// Levels written per character (also the Fig. 8 tint), chosen from its projected height.
const uint kLevelFar = 0u;   // four limbs to the wrists and ankles; spine and neck one bone each
const uint kLevelMid = 1u;   // every joint but the fingers
const uint kLevelNear = 2u;  // every joint
const uint kLevelCount = 3u;

// CoverageMask.state: what the pass keeps from frame to frame.
const uint kStatePartBits = 31u;       // bits 0..4: parts whose sphere is on screen (area > 0),
                                       //   when measured (kCoverageWriteAreas), else 0
const uint kStateInitialized = 32u;    // bit 5: `level` was chosen by this pass
const uint kStateTimerShift = 6u;      // bits 6..15: time since the level changed, 1/256 s units,
const uint kStateTimerMax = 1023u;     //   saturating at 4 s
const float kStateTimerUnits = 256.0;  // units per second
const uint kStatePhaseShift = 16u;     // bits 16..31: the phase seen last frame, floor(phase·65535)

// Push constants: the camera changes every frame, so it travels here rather than in a
// buffer that frames in flight would share.
THRONG_STRUCT(CoveragePush) {
  mat4 view;              // world → camera (a lookAt matrix: the camera looks down −z)
  vec4 viewport;          // width, height, focal length f in pixels, near plane distance
  vec4 frustum;           // (f, W/2)/|(f, W/2)| and (f, H/2)/|(f, H/2)|: unit side-plane normals
  uint characterCount;    // the chunk [firstCharacter, firstCharacter + characterCount)
  uint firstCharacter;    // masks and areas are indexed by the global character index
  uint jointCount;
  uint flags;             // kCoverageReadJoints | kCoverageWriteAreas
};

// The camera of CoveragePush as a uniform block, for the root motion pass that does the frame's
// coverage (root_motion_coverage.comp): the two pushes together pass the 128 bytes every device
// allows (lavapipe allows no more), and one block serves every group of the frame.
THRONG_STRUCT(CoverageView) {
  mat4 view;
  vec4 viewport;
  vec4 frustum;
};

// One body part's bounding sphere (the paper's eqs. 1–9), measured for the areas output.
THRONG_STRUCT(CoveragePart) {
  vec4 centre;            // xyz: mean character-space position of the centre joint; w: radius (m)
  uint joint;             // the centre joint
  float bonePoint;        // the centre is A·(0, bonePoint, 0, 1): 1 = bone end, 0.5 for the root
  int parent;             // the centre joint's parent (its bone starts there), -1 for the root
  uint pad0;
};

// The joint whose point a part's bone starts from (bonePoint's `parent`): the centre joint's
// parent, or for the root its own point (its bone is centred on it).
#ifdef __cplusplus
inline
#endif
uint partBoneStart(CoveragePart part) { return part.parent < 0 ? part.joint : uint(part.parent); }

// One level: what is synthesized and what is drawn, and its projected-height band.
THRONG_STRUCT(CoverageLevel) {
  uint synthLo;           // joints the pose pass synthesizes (closed under ancestors)
  uint synthHi;
  uint drawLo;            // joints the renderer draws (a bone from boneFrom, see CoverageParts)
  uint drawHi;
  float enterHeight;      // pixels: a lower level rises to this one at a height >= this
  float leaveHeight;      // pixels: this level drops to a lower one under this (hysteresis)
  uint pad0;
  uint pad1;
};

// Uniform buffer (std140): what changes only with the skeleton or the thresholds.
THRONG_STRUCT(CoverageParts) {
  uint offScreenLo;       // joints synthesized for a character off screen: none (nothing of it
  uint offScreenHi;       //   is posed or drawn), every joint when the near threshold is 0
  uint allLo;             // every joint of the skeleton
  uint allHi;
  vec4 body;              // x: standing height (m at scale 1); y: least seconds between level
                          // changes; z, w: slow and fast cycle seconds (time from the phase)
  CoverageLevel levels[3];
  CoveragePart parts[5];
  uvec4 boneFrom[12];     // byte level·64 + j: the joint a drawn joint's bone starts at; 255:
                          // its own bone (from its parent)
  vec4 boneRadius[48];    // float level·64 + j: radius of that long bone over joint j's own
};

// What the far body (joint_far_body.glsl) reads of a cached pose, written by cache_fill.comp
// beside the pose: the character-space points (JointPoint) of the torso's and the legs' centre
// joints (CoverageParts.parts) and of their parents. Read from this small table rather than from
// the cache's points, hundreds of bytes apart: the far-body pass reads it for every cached
// character on screen, and on a CPU those scattered points miss the cache.
THRONG_STRUCT(FarBodyPose) {
  vec4 torso;
  vec4 torsoParent;       // the root's own point again where the centre joint is the root
  vec4 leftLeg;
  vec4 leftLegParent;
  vec4 rightLeg;
  vec4 rightLegParent;
};

// Per character output (std430), also read back as the previous frame's mask.
THRONG_STRUCT(CoverageMask) {
  uint lo;                // joints synthesized this frame, 0..31
  uint hi;                // 32..63
  uint level;             // kLevelFar, kLevelMid or kLevelNear
  uint state;             // kState* fields
};

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
