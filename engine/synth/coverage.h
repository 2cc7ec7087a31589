#pragma once
// Coverage LOD: per character, a level (far / mid / near, synth::levelJoints) chosen from
// its projected height with hysteresis, changing only at a walk-cycle end and at most once a
// second while on screen; five bounding spheres (elbows, mid-spine, knees; the paper's eqs. 1–9,
// docs/design.md) tell whether any of it is on screen. Output per character: the 64-bit mask of
// joints to synthesize, the level and the pass's state; optionally the five areas. CPU twin:
// coverageCpu.
#include <array>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "crowd/crowd.h"
#include "gpu/program.h"
#include "shaders/coverage_types.h"
#include "synth/body_parts.h"
#include "synth/gpu_types.h"

namespace throng::synth {

using gpu_types::CoverageLevel;
using gpu_types::CoverageMask;
using gpu_types::CoveragePart;
using gpu_types::CoverageParts;
using gpu_types::CoveragePush;
using gpu_types::CoverageView;
static_assert(sizeof(CoveragePush) == 112, "CoveragePush must match the GLSL push block");
static_assert(sizeof(CoverageView) == 96, "CoverageView must match the GLSL std140 block");
static_assert(sizeof(CoveragePart) == 32, "CoveragePart must match the GLSL std140 struct");
static_assert(sizeof(CoverageLevel) == 32, "CoverageLevel must match the GLSL std140 struct");
static_assert(sizeof(CoverageParts) == 1248, "CoverageParts must match the GLSL std140 block");
static_assert(sizeof(CoverageMask) == 16, "CoverageMask must match the GLSL std430 struct");
using gpu_types::FarBodyPose;
static_assert(sizeof(FarBodyPose) == 96, "FarBodyPose must match the GLSL std430 struct");

// Default thresholds: projected standing height in pixels (f·H/z) from which a character is
// mid and near. Every level draws four limbs; mid keeps elbows and knees from 56 px, near
// every joint from 140 px. Measured by test_coverage.cpp.
constexpr float kDefaultMidPixels = 56.0f;
constexpr float kDefaultNearPixels = 140.0f;

struct CoverageThresholds {
  float midHeight = kDefaultMidPixels;    // pixels; 0: never below mid
  float nearHeight = kDefaultNearPixels;  // pixels; 0: always near, every joint even off screen
  float hysteresis = 0.15f;       // a level is left under (1 − hysteresis) × its entry height
  float minChangeSeconds = 1.0f;  // least time between two level changes of a character
  static CoverageThresholds uniform(float value) { return {value, value}; }
  // The two-level form the options expose: the mid and near entry heights.
  static CoverageThresholds levels(float mid, float near) { return {mid, near}; }
};

// The camera as the pass sees it: view matrix, viewport, focal length in pixels.
struct CoverageCamera {
  glm::mat4 view{1.0f};  // world → camera, looking down −z (glm::lookAt)
  uint32_t width = 1280;
  uint32_t height = 720;
  float focalPixels = 869.12f;  // (H/2) / tan(fovy/2)
  float nearPlane = 0.1f;
};
CoverageCamera coverageCamera(const glm::mat4& view, float fovYDegrees, uint32_t width,
                              uint32_t height, float nearPlane);
// The camera as the shaders take it: view, viewport (W, H, f, near) and side-plane normals.
CoverageView coverageView(const CoverageCamera& camera);

// The uniform buffer contents (skeleton, levels, thresholds) and the push constants (camera +
// chunk). Throws Error on a negative or NaN threshold or hysteresis outside [0, 1).
CoverageParts makeCoverageParts(const BodyParts& parts, const CoverageThresholds& thresholds);
CoveragePush makeCoveragePush(const CoverageCamera& camera, uint32_t jointCount,
                              uint32_t firstCharacter, uint32_t characterCount, uint32_t flags);

// Eqs. 1–9 for one sphere (world centre, radius in metres): its screen area in pixels. The
// cases, in order: containing the camera → W·H; wholly nearer than the near plane (which
// includes wholly behind the camera) → 0; outside one of the four side planes → 0; straddling
// the camera plane (centre depth ≤ r) → W·H, as the projection is unbounded there; otherwise
// π f² r² √(l² − r²) / (z² − r²)^{3/2}, clamped to W·H. An ellipse partly off screen counts
// its full area (not just its visible part): the test is conservative, a part at the screen
// edge keeps the detail it would have in the middle.
float sphereCoveragePixels(const CoveragePush& push, glm::vec3 worldCentre, float radius);

// World → camera space looking down +z.
glm::vec3 cameraSpace(const CoveragePush& push, glm::vec3 world);
// Whether a sphere at camera-space `o` meets the frustum: sphereCoveragePixels' cases without
// the area (that area is > 0 exactly when this holds).
bool sphereInFrustum(const CoveragePush& push, glm::vec3 o, float radius);
// f·H/z for a character H tall (metres) whose middle is at camera-space `middle`: see
// coverage_common.glsl.
float projectedHeight(const CoveragePush& push, glm::vec3 middle, float height);
// A character's standing height on screen in pixels (bodyOnScreenHeight's h in coverage_mask.glsl).
float characterHeightPixels(const CoveragePush& push, const CoverageParts& parts,
                            glm::vec4 placement, glm::vec4 motion);
// Whether the body sphere, grown by `reach` of the character's height, meets the view
// (bodyWithinReach in coverage_common.glsl).
bool bodyWithinReach(const CoveragePush& push, const CoverageParts& parts, glm::vec4 placement,
                     glm::vec4 motion, float reach);

// The CPU twin of coverage.comp for one character: `joints` are its J points (nullptr: the
// centres are estimated from the placement); `previous` is last frame's mask, which says which
// centre joints the pose pass wrote and holds the level state. The five part spheres are
// measured only when push.flags has kCoverageWriteAreas (into `areas`, 5 floats, if not null).
CoverageMask coverageCharacter(const CoveragePush& push, const CoverageParts& parts,
                               glm::vec4 placement, glm::vec4 motion, const JointPoint* joints,
                               const CoverageMask& previous, float* areas);

// The whole crowd on the CPU; `masks` (one per character) is read as the previous masks and
// overwritten; `joints` is empty or crowd.size() × jointCount; `areas` is empty or 5 per character.
void coverageCpu(const CoverageCamera& camera, const CoverageParts& parts, uint32_t jointCount,
                 const crowd::Crowd& crowd, std::span<const JointPoint> joints,
                 std::span<CoverageMask> masks, std::span<float> areas);

// True when every active joint's parent is active (the invariant the pose pass relies on).
bool parentsBeforeChildren(uint64_t mask, std::span<const int32_t> parents);
inline uint64_t maskBits(const CoverageMask& m) {
  return uint64_t(m.lo) | (uint64_t(m.hi) << 32);
}

// The coverage pass as a job: one invocation per character of the chunk. Masks obey
// parent-before-child by construction: each level's joint set and the base set are closed under
// ancestors (levelJoints).
//
// Sphere centres: without `joints`, each centre is the joint's mean character-space position
// placed by the character's root (placement, heading, scale) — no dependency on the pose pass,
// so coverage can run right after root motion in the same frame. With `joints` (the points of
// the last pose pass), a centre joint that was active in the mask read from `masks` (last
// frame's) is taken from its bone, A·(0, bonePoint, 0, 1); the others are estimated, because
// the pose pass did not write them. Zero-filled masks (a new crowd) mean "all estimated".
struct CoverageJob {
  const crowd::CrowdBuffers* crowd =
      nullptr;                          // input: placement (position, heading), motion (scale)
  const gpu::Buffer* parts = nullptr;   // input: uniform CoverageParts (makeCoverageParts)
  const gpu::Buffer* joints = nullptr;  // optional input: last pose pass' JointPoint output
  const gpu::Buffer* masks = nullptr;   // input/output: CoverageMask per character
  const gpu::Buffer* areas = nullptr;   // optional output: 5 floats per character
  CoverageCamera camera;
  uint32_t jointCount = 0;
  uint32_t firstCharacter = 0;    // the chunk [first, first + count)
  uint32_t characterCount = 0;    // 0: every character from firstCharacter
  VkDeviceSize jointsOffset = 0;  // where the chunk's joints start in `joints`

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const gpu::ComputeProgram& program) const;
};

// The compiled coverage.comp (no specialization: one program serves every skeleton).
gpu::ComputeProgram makeCoverageProgram(const gpu::Context& context);

}  // namespace throng::synth
