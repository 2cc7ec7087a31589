#pragma once
// A character's synthesized motion as joint-local transforms per frame, the form animation
// files store: recorded from the CPU reference synthesizer (the same math as the GPU passes),
// converted to BVH (every joint with position and rotation channels, so animated offsets
// survive) and, in gltf_export.h, to glTF 2.0.
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "anim/clip.h"
#include "anim/motion_texture.h"
#include "anim/reference_synth.h"

namespace throng::anim {

struct JointAnimation {
  std::string name;             // e.g. "agent_17"
  Skeleton skeleton;            // names and parents (offsets: the first frame's)
  float frameTime = 1.0f / 30;  // seconds per frame
  int frameCount = 0;
  // frameCount × jointCount, joint-local (the root: in the world).
  std::vector<glm::quat> rotations;
  std::vector<glm::vec3> translations;

  int jointCount() const { return skeleton.jointCount(); }
  const glm::quat& rotation(int frame, int joint) const { return rotations[index(frame, joint)]; }
  const glm::vec3& translation(int frame, int joint) const {
    return translations[index(frame, joint)];
  }
  size_t index(int frame, int joint) const {
    return size_t(frame) * size_t(jointCount()) + size_t(joint);
  }
};

// How one character is driven while it is recorded (as the crowd drives it).
struct RecordOptions {
  int frames = 90;
  float dt = 1.0f / 30;
  Steering steering = Steering::KeepHeading;
  // The speed change each step applies (as the crowd's speed schedule gives them); empty or
  // shorter than `frames`: no change in the steps past its end.
  std::vector<SpeedRetarget> retargets;
  uint32_t character = 0;  // the character's index (speed changes are drawn per character)
};

// An empty animation of `skeleton` (which must have the pair's joint count) at `dt` per frame;
// appendPose adds the character's pose at its current state as the next frame.
JointAnimation beginAnimation(const MotionPair& pair, const Skeleton& skeleton, float dt,
                              std::string name);
void appendPose(const MotionPair& pair, const glm::vec4& placement, const glm::vec4& motion,
                JointAnimation& animation);

// Poses the character at its current state, then steps it, `frames` times. `skeleton` gives the
// joint names (it must have the pair's joint count).
JointAnimation recordCharacter(const MotionPair& pair, const Skeleton& skeleton,
                               glm::vec4 placement, glm::vec4 motion, const RecordOptions& options);

// World positions of every joint at a frame (forward kinematics of the local transforms).
std::vector<glm::vec3> worldPositions(const JointAnimation& animation, int frame);

// As a BVH clip: every joint has Xposition Yposition Zposition Zrotation Xrotation Yrotation.
RawClip toBvhClip(const JointAnimation& animation);

// Euler angles in degrees (z, x, y) with R = Rz · Rx · Ry, BVH's `Zrotation Xrotation Yrotation`.
glm::vec3 eulerZxyDegrees(const glm::quat& q);

}  // namespace throng::anim
