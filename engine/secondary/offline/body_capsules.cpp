#include "secondary/offline/body_capsules.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"

namespace throng::secondary {

std::vector<BoneCapsule> defaultBodyCapsules() {
  std::vector<BoneCapsule> bones = {// Built-in gait (and CMU, which shares most names).
                                    {"Spine", 0.10f},
                                    {"Spine1", 0.10f},
                                    {"Spine2", 0.11f},
                                    {"Spine3", 0.11f},
                                    {"Neck", 0.06f},
                                    {"Head", 0.08f},
                                    {"LeftArm", 0.05f},
                                    {"RightArm", 0.05f},
                                    {"LeftForeArm", 0.045f},
                                    {"RightForeArm", 0.045f},
                                    {"LeftHand", 0.04f},
                                    {"RightHand", 0.04f},
                                    {"LeftUpLeg", 0.08f},
                                    {"RightUpLeg", 0.08f},
                                    {"LeftLeg", 0.07f},
                                    {"RightLeg", 0.07f},
                                    {"LeftFoot", 0.05f},
                                    {"RightFoot", 0.05f},
                                    // CMU only.
                                    {"LowerBack", 0.10f},
                                    {"Neck1", 0.06f},
                                    // Bandai Namco.
                                    {"Chest", 0.11f},
                                    {"UpperArm_L", 0.05f},
                                    {"UpperArm_R", 0.05f},
                                    {"LowerArm_L", 0.045f},
                                    {"LowerArm_R", 0.045f},
                                    {"Hand_L", 0.04f},
                                    {"Hand_R", 0.04f},
                                    {"UpperLeg_L", 0.08f},
                                    {"UpperLeg_R", 0.08f},
                                    {"LowerLeg_L", 0.07f},
                                    {"LowerLeg_R", 0.07f},
                                    {"Foot_L", 0.05f},
                                    {"Foot_R", 0.05f}};
  return bones;
}

std::vector<Capsule> resolveCapsules(const PrimaryGraph& graph,
                                     const std::vector<BoneCapsule>& bones) {
  std::vector<Capsule> out;
  for (const BoneCapsule& bone : bones) {
    if (!(bone.radius > 0.0f))
      fail("body capsule on joint ", bone.joint, ": radius ", bone.radius, " must be > 0");
    auto it = std::find(graph.jointNames.begin(), graph.jointNames.end(), bone.joint);
    if (it == graph.jointNames.end()) continue;
    const uint32_t j = uint32_t(it - graph.jointNames.begin());
    const int32_t parent = graph.parents[j];
    out.push_back({parent < 0 ? j : uint32_t(parent), j, bone.radius});
  }
  return out;
}

std::vector<CapsuleShape> capsulesAt(const PrimaryGraph& graph,
                                     const std::vector<Capsule>& capsules, uint32_t node) {
  const NodeJoint* pose = graph.pose(node);
  std::vector<CapsuleShape> out;
  out.reserve(capsules.size());
  for (const Capsule& c : capsules)
    out.push_back({pose[c.a].position, pose[c.b].position, c.radius});
  return out;
}

float segmentDistance(glm::vec3 p, glm::vec3 a, glm::vec3 b) {
  const glm::vec3 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + t * ab));
}

std::vector<uint32_t> neckShoulderJoints(const PrimaryGraph& graph) {
  std::vector<uint32_t> out;
  for (uint32_t j = 0; j < graph.jointCount; ++j) {
    std::string name = graph.jointNames[j];
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    for (const char* key : {"neck", "shoulder", "clavicle", "collar"})
      if (name.find(key) != std::string::npos) {
        out.push_back(j);
        break;
      }
  }
  return out;
}

}  // namespace throng::secondary
