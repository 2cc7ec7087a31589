#pragma once
// The five body parts of the pixel-coverage LOD (the paper's eqs. 1–9, docs/design.md): which joint
// is each part's sphere centre, the sphere's radius and which joints the part makes active. Found
// from the joint names (default, CMU, Bandai Namco and Mixamo-like naming) or, when names do not
// say, from the rest pose's geometry.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/motion_texture.h"
#include "anim/skeleton.h"

namespace throng::synth {

enum class BodyPartId : uint32_t {
  LeftArm = 0,
  RightArm = 1,
  Torso = 2,
  LeftLeg = 3,
  RightLeg = 4
};
constexpr int kBodyPartCount = 5;
const char* bodyPartName(int part);

struct BodyPart {
  int centreJoint = -1;        // elbow, elbow, mid-spine, knee, knee
  float radius = 0.0f;         // metres (skeleton units), before the character's scale
  std::vector<int> joints;     // the part's joints (for the torso: base joints included)
  uint64_t activates = 0;      // joints it makes active: its joints and their ancestors, minus base
  glm::vec3 meanCentre{0.0f};  // centre joint's character-space position averaged over the cycle
  int upper = -1;              // limbs: the centre's parent (shoulder, hip)
  int lower = -1;              // limbs: the centre's child towards the limb's tip (wrist, ankle)
  int tip = -1;  // limbs: the lower joint's child towards the tip (finger, toe); -1: none
};

struct BodyParts {
  int jointCount = 0;
  std::array<BodyPart, kBodyPartCount> parts;
  uint64_t baseMask = 0;  // always active: root, the pelvis and the spine up to mid-spine
  uint64_t allMask = 0;
  std::string method;  // "names" or "geometry": how the parts were found
  std::vector<int32_t> parents;
  int pelvis = -1;  // where the legs leave the trunk
  int chest = -1;   // where the arms leave it
  int head = -1;
  // From the motion (setMeanCentres; before it, from the rest pose and unit values):
  float height = 0.0f;  // standing height, lowest to highest joint, averaged over the cycles
  float slowCycleSeconds = 1.0f;  // the clips' durations
  float fastCycleSeconds = 1.0f;
  std::vector<float> jointRadius;  // drawn radius of each joint's bone; empty: unknown
};

// The joints a coverage LOD level synthesizes and draws. Near: all of them. Mid: trunk, head,
// arms to the wrist, legs to the toes; the spine and neck each drawn as one bone. Far: the
// same trunk, each limb as a bone from the body to its shoulder or hip and one long bone from
// there to the wrist or ankle. A drawn joint's bone starts at its nearest drawn ancestor (or the
// pelvis), and a long bone is as thick as the thickest bone it stands for.
struct LevelJoints {
  uint64_t synth = 0;                // closed under ancestors (the pose pass needs parents first)
  uint64_t draw = 0;                 // a subset of synth
  std::array<uint8_t, 64> boneFrom;  // per joint: where its drawn bone starts; 255: its parent
  std::array<float, 64> boneRadius;  // per joint: that bone's radius over the joint's own
};
std::array<LevelJoints, 3> levelJoints(const BodyParts& parts);

// Throws Error (naming the skeleton's size and what is missing) when the skeleton has more
// than 64 joints, is not stored parents-first, or has no two arms and two legs hanging off a
// root→head chain.
BodyParts describeBodyParts(const anim::Skeleton& skeleton);

// The rest-pose fallback for sphere centres: each centre joint's character-space position
// averaged over both clips' frames (the coverage pass uses it when a centre joint was not
// synthesized last frame); also the height, cycle durations and joint radii from the pair.
// Throws Error when the pair's joint count differs.
void setMeanCentres(BodyParts& parts, const anim::MotionPair& pair);

// Rest-pose joint positions (offsets accumulated down the hierarchy), for tests and tools.
std::vector<glm::vec3> restPositions(const anim::Skeleton& skeleton);

// Active joints of a 64-bit mask, for logs and tests.
int countJoints(uint64_t mask);

}  // namespace throng::synth
