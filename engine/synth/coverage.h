#pragma once
// Pixel-coverage LOD (DESIGN eqs. 1–9): per character, five bounding spheres (elbows,
// mid-spine, knees) projected to screen ellipses; a part whose area in pixels reaches its
// threshold makes its joints active. Output per character: a 64-bit joint mask, a level
// (far / mid / near) and the parts' bits; optionally the five areas. CPU twin: coverageCpu.
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

using gpu_types::CoverageMask;
using gpu_types::CoveragePart;
using gpu_types::CoverageParts;
using gpu_types::CoveragePush;
static_assert(sizeof(CoveragePush) == 112, "CoveragePush must match the GLSL push block");
static_assert(sizeof(CoveragePart) == 48, "CoveragePart must match the GLSL std140 struct");
static_assert(sizeof(CoverageParts) == 256, "CoverageParts must match the GLSL std140 block");
static_assert(sizeof(CoverageMask) == 16, "CoverageMask must match the GLSL std430 struct");

// Default thresholds (pixels of a part's projected sphere), the paper's three levels on the
// built-in 25-joint skeleton: far = 4 joints (Hips, Spine, Spine1, Spine2: always active), mid
// = 7 (the torso part adds Spine3, Neck, Head), near = 25 (the limbs). Bone-path radii at scale
// 1: torso 0.34 m, arms 0.46 m, legs 0.55 m. With the default camera (1280×720, fovy 45°:
// f = 869 px), a character facing a camera 1.6 m above the ground switches far → mid at 65.5 m
// (torso sphere ≥ 64 px) and mid → near at 17.8 m (arms) and 21.2 m (legs) (≥ 1,600 px); in
// between the legs alone make it a 15-joint "mid". Measured by test_coverage.cpp.
constexpr float kDefaultMidPixels = 64.0f;
constexpr float kDefaultNearPixels = 1600.0f;

// Per-part pixel thresholds (order: gpu_types::kPartLeftArm … kPartRightLeg). A part is active
// when its area >= its threshold: 0 makes it always active (even off screen), +inf never.
struct CoverageThresholds {
  std::array<float, 5> pixels{kDefaultNearPixels, kDefaultNearPixels, kDefaultMidPixels, kDefaultNearPixels,
                              kDefaultNearPixels};
  static CoverageThresholds uniform(float value) { return {{value, value, value, value, value}}; }
  // The two-level form the options expose: the torso at `mid`, the four limbs at `near`.
  static CoverageThresholds levels(float mid, float near) { return {{near, near, mid, near, near}}; }
};

// The camera as the pass sees it: view matrix, viewport, focal length in pixels.
struct CoverageCamera {
  glm::mat4 view{1.0f};       // world → camera, looking down −z (glm::lookAt)
  uint32_t width = 1280;
  uint32_t height = 720;
  float focalPixels = 869.12f;  // (H/2) / tan(fovy/2)
  float nearPlane = 0.1f;
};
CoverageCamera coverageCamera(const glm::mat4& view, float fovYDegrees, uint32_t width, uint32_t height,
                              float nearPlane);

// The uniform buffer contents (skeleton + thresholds) and the push constants (camera + chunk).
CoverageParts makeCoverageParts(const BodyParts& parts, const CoverageThresholds& thresholds);
CoveragePush makeCoveragePush(const CoverageCamera& camera, uint32_t jointCount, uint32_t firstCharacter,
                              uint32_t characterCount, uint32_t flags);

// Eqs. 1–9 for one sphere (world centre, radius in metres): its screen area in pixels. The
// cases, in order: containing the camera → W·H; wholly nearer than the near plane (which
// includes wholly behind the camera) → 0; outside one of the four side planes → 0; straddling
// the camera plane (centre depth ≤ r) → W·H, as the projection is unbounded there; otherwise
// π f² r² √(l² − r²) / (z² − r²)^{3/2}, clamped to W·H. An ellipse partly off screen counts
// its full area (not just its visible part): the test is conservative, a part at the screen
// edge keeps the detail it would have in the middle.
float sphereCoveragePixels(const CoveragePush& push, glm::vec3 worldCentre, float radius);

// The CPU twin of coverage.comp for one character: `joints` are its J matrices (nullptr: the
// centres are estimated from the placement); `previous` is last frame's mask, which says which
// centre joints the pose pass wrote. `areas` (5 floats) may be nullptr.
CoverageMask coverageCharacter(const CoveragePush& push, const CoverageParts& parts, glm::vec4 placement,
                               glm::vec4 motion, const JointMatrix* joints, const CoverageMask& previous,
                               float* areas);

// The whole crowd on the CPU; `masks` (one per character) is read as the previous masks and
// overwritten; `joints` is empty or crowd.size() × jointCount; `areas` is empty or 5 per character.
void coverageCpu(const CoverageCamera& camera, const CoverageParts& parts, uint32_t jointCount,
                 const crowd::Crowd& crowd, std::span<const JointMatrix> joints, std::span<CoverageMask> masks,
                 std::span<float> areas);

// True when every active joint's parent is active (the invariant the pose pass relies on).
bool parentsBeforeChildren(uint64_t mask, std::span<const int32_t> parents);
inline uint64_t maskBits(const CoverageMask& m) { return uint64_t(m.lo) | (uint64_t(m.hi) << 32); }

// The coverage pass as a job: one invocation per character of the chunk. Masks obey
// parent-before-child by construction: each part's joint set is closed under ancestors when the
// body parts are described (an active joint makes its ancestors active), and the union of
// closed sets is closed.
//
// Sphere centres: without `joints`, each centre is the joint's mean character-space position
// placed by the character's root (placement, heading, scale) — no dependency on the pose pass,
// so coverage can run right after root motion in the same frame. With `joints` (the matrices
// of the last pose pass), a centre joint that was active in the mask read from `masks` (last
// frame's) is taken from its matrix, A·(0, bonePoint, 0, 1); the others are estimated, because
// the pose pass did not write them. Zero-filled masks (a new crowd) mean "all estimated".
struct CoverageJob {
  const crowd::CrowdBuffers* crowd = nullptr;  // input: placement (position, heading), motion (scale)
  const gpu::Buffer* parts = nullptr;          // input: uniform CoverageParts (makeCoverageParts)
  const gpu::Buffer* joints = nullptr;         // optional input: last pose pass' JointMatrix output
  const gpu::Buffer* masks = nullptr;          // input/output: CoverageMask per character
  const gpu::Buffer* areas = nullptr;          // optional output: 5 floats per character
  CoverageCamera camera;
  uint32_t jointCount = 0;
  uint32_t firstCharacter = 0;                 // the chunk [first, first + count)
  uint32_t characterCount = 0;                 // 0: every character from firstCharacter
  VkDeviceSize jointsOffset = 0;               // where the chunk's joints start in `joints`

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const gpu::ComputeProgram& program) const;
};

// The compiled coverage.comp (no specialization: one program serves every skeleton).
gpu::ComputeProgram makeCoverageProgram(const gpu::Context& context);

}  // namespace throng::synth
