// Structs of the pixel-coverage pass (DESIGN eqs. 1–9), shared by C++ and GLSL like
// shared_types.h; C++ includes this file through synth/coverage.h, which checks the sizes.
#ifndef THRONG_COVERAGE_TYPES_H
#define THRONG_COVERAGE_TYPES_H

#include "shared_types.h"

#ifdef __cplusplus
namespace throng::gpu_types {
#endif

// The five bounding spheres, in this order everywhere (masks' part bits, areas).
const uint kPartLeftArm = 0u;
const uint kPartRightArm = 1u;
const uint kPartTorso = 2u;
const uint kPartLeftLeg = 3u;
const uint kPartRightLeg = 4u;
const uint kCoveragePartCount = 5u;

// CoveragePush.flags
const uint kCoverageReadJoints = 1u;  // sphere centres from the joint matrices (else estimated)
const uint kCoverageWriteAreas = 2u;  // fill the optional areas buffer

// Levels written per character (for the Fig. 8 tint).
const uint kLevelFar = 0u;   // only the always-active base joints
const uint kLevelMid = 1u;   // some parts
const uint kLevelNear = 2u;  // every joint

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

// One body part: its sphere and the joints it makes active.
THRONG_STRUCT(CoveragePart) {
  vec4 centre;            // xyz: mean character-space position of the centre joint; w: radius (m)
  uint joint;             // the centre joint
  float threshold;        // pixels; the part is active when its area >= threshold
  float bonePoint;        // the centre is A·(0, bonePoint, 0, 1): 1 = bone end, 0.5 for the root
  uint pad0;
  uint maskLo;            // joints this part activates (closed under ancestors, minus base)
  uint maskHi;
  uint pad1;
  uint pad2;
};

// Uniform buffer (std140): what changes only with the skeleton or the thresholds.
THRONG_STRUCT(CoverageParts) {
  uint baseLo;            // joints active at every distance (root, pelvis, lower spine)
  uint baseHi;
  uint allLo;             // every joint of the skeleton
  uint allHi;
  CoveragePart parts[5];
};

// Per character output (std430), also read back as the previous frame's mask.
THRONG_STRUCT(CoverageMask) {
  uint lo;                // active joints 0..31
  uint hi;                // active joints 32..63
  uint level;             // kLevelFar, kLevelMid or kLevelNear
  uint parts;             // bit k: part k's area reached its threshold
};

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
