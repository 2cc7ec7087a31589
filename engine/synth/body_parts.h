#pragma once
// The five body parts of the pixel-coverage LOD (DESIGN eqs. 1–9): which joint is each part's
// sphere centre, the sphere's radius and which joints the part makes active. Found from the
// joint names (default, CMU, Bandai Namco and Mixamo-like naming) or, when names do not say,
// from the rest pose's geometry.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/motion_texture.h"
#include "anim/skeleton.h"

namespace throng::synth {

enum class BodyPartId : uint32_t { LeftArm = 0, RightArm = 1, Torso = 2, LeftLeg = 3, RightLeg = 4 };
constexpr int kBodyPartCount = 5;
const char* bodyPartName(int part);

struct BodyPart {
  int centreJoint = -1;        // elbow, elbow, mid-spine, knee, knee
  float radius = 0.0f;         // metres (skeleton units), before the character's scale
  std::vector<int> joints;     // the part's joints (for the torso: base joints included)
  uint64_t activates = 0;      // joints it makes active: its joints and their ancestors, minus base
  glm::vec3 meanCentre{0.0f};  // centre joint's character-space position averaged over the cycle
};

struct BodyParts {
  int jointCount = 0;
  std::array<BodyPart, kBodyPartCount> parts;
  uint64_t baseMask = 0;       // always active: root, the pelvis and the spine up to mid-spine
  uint64_t allMask = 0;
  std::string method;          // "names" or "geometry": how the parts were found
};

// Throws Error (naming the skeleton's size and what is missing) when the skeleton has more
// than 64 joints, is not stored parents-first, or has no two arms and two legs hanging off a
// root→head chain.
BodyParts describeBodyParts(const anim::Skeleton& skeleton);

// The rest-pose fallback for sphere centres: each centre joint's character-space position
// averaged over both clips' frames (the coverage pass uses it when a centre joint was not
// synthesized last frame). Throws Error when the pair's joint count differs.
void setMeanCentres(BodyParts& parts, const anim::MotionPair& pair);

// Rest-pose joint positions (offsets accumulated down the hierarchy), for tests and tools.
std::vector<glm::vec3> restPositions(const anim::Skeleton& skeleton);

// Active joints of a 64-bit mask, for logs and tests.
int countJoints(uint64_t mask);

}  // namespace throng::synth
