#pragma once
// The CPU reference synthesizer: docs/design.md's blend, hierarchy and root motion for one
// character, in plain C++. Every GPU synthesis pass is tested against it, and the bench runs
// it (one and many threads) as the paper's CPU baseline.
#include <span>

#include <glm/glm.hpp>

#include "anim/motion_texture.h"
#include "anim/root_motion.h"

namespace throng::anim {

// Mirrors shaders/shared_types.h: placement = (x, y, z, heading), motion = (phase, w, wTarget,
// scale).
struct CharacterRef {
  glm::vec4& placement;
  glm::vec4& motion;
};

// Eq. 10: advances the phase by dt, moves the root by the blended displacement between the two
// phases (each clip's root interpolated between its rows, so the step is continuous in the
// phase) rotated by the heading and scaled, and switches w to wTarget only when a cycle ends.
void stepCharacter(const MotionPair& pair, glm::vec4& placement, glm::vec4& motion, float dt,
                   Steering steering);
// The same with a speed change: the new target is set before a cycle end in this step applies it.
void stepCharacter(const MotionPair& pair, glm::vec4& placement, glm::vec4& motion, float dt,
                   Steering steering, const SpeedRetarget& retarget, uint32_t character);

// Joint points for one character (per joint its position and its bone's drawn radius, matching
// gpu_types::JointPoint; the draw matrices A_j = M·O·F follow, gpu_types::boneMatrix). `out`
// holds jointCount vec4.
void poseCharacter(const MotionPair& pair, const glm::vec4& placement, const glm::vec4& motion,
                   std::span<glm::vec4> out);

// Where a clip is sampled at a phase in [0, 1): between rows `row` and `next` (the row after
// the last is row 0: clips are cycles) at fraction t. Rotations are slerped and offsets lerped
// between the two rows, so the pose moves continuously with the phase. A phase within kRowSnap
// rows of a row is taken as on it.
constexpr float kRowSnap = 1e-4f;
struct ClipSample {
  int row = 0;
  int next = 0;
  float t = 0.0f;
};
ClipSample clipSample(float phase, int frames);

// The pose at a phase of both clips and speed weight w, placed by heading, origin and scale;
// heading 0, origin 0, scale 1 gives the character-space pose the motion cache stores.
void poseCharacterAt(const MotionPair& pair, float phase, float w, float heading, glm::vec3 origin,
                     float scale, std::span<glm::vec4> out);

// Character-space joint positions and global rotations (for tests and metrics).
struct PoseJoint {
  glm::vec3 position;
  glm::vec4 rotation;
};
void poseCharacterSpace(const MotionPair& pair, float phase, float w, std::span<PoseJoint> out);

}  // namespace throng::anim
