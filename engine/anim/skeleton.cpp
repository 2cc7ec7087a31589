#include "anim/skeleton.h"

#include <algorithm>

namespace throng::anim {

std::vector<int32_t> Skeleton::parents() const {
  std::vector<int32_t> result;
  result.reserve(joints.size());
  for (const Joint& j : joints) result.push_back(j.parent);
  return result;
}

int Skeleton::findJoint(const std::string& name) const {
  for (size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

bool Skeleton::sameTopology(const Skeleton& other) const {
  return parents() == other.parents();
}

std::vector<bool> Skeleton::placementJoints() const {
  std::vector<glm::vec3> rest;
  std::vector<bool> translationOnly;
  for (const Joint& joint : joints) {
    const bool inRange = joint.parent >= 0 && joint.parent < int(rest.size());
    rest.push_back((inRange ? rest[size_t(joint.parent)] : glm::vec3(0.0f)) + joint.offset);
    const bool rotates = std::any_of(joint.channels.begin(), joint.channels.end(), [](Channel c) {
      return c == Channel::Xrotation || c == Channel::Yrotation || c == Channel::Zrotation;
    });
    translationOnly.push_back(!joint.channels.empty() && !rotates);
  }
  return anim::placementJoints(parents(), rest, translationOnly);
}

std::vector<bool> placementJoints(std::span<const int32_t> parents,
                                  std::span<const glm::vec3> positions,
                                  const std::vector<bool>& translationOnly) {
  const size_t n = std::min(parents.size(), positions.size());
  std::vector<bool> placement(parents.size(), false);
  if (n < 3 || parents[0] >= 0) return placement;
  float lowest = positions[1].y, highest = positions[0].y;
  for (size_t j = 1; j < n; ++j) lowest = std::min(lowest, positions[j].y);
  for (size_t j = 0; j < n; ++j) highest = std::max(highest, positions[j].y);
  const float height = highest - std::min(lowest, positions[0].y);
  if (!(height > 0.0f)) return placement;
  const bool onlyTranslates = !translationOnly.empty() && translationOnly[0];
  const bool atGround = positions[0].y <= lowest + 0.1f * height;
  if (!onlyTranslates && !atGround) return placement;
  placement[0] = true;
  for (size_t j = 1; j < n; ++j)
    if (parents[j] == 0 && glm::length(positions[j] - positions[0]) > 0.25f * height)
      placement[j] = true;
  return placement;
}

uint64_t drawnBoneMask(const std::vector<bool>& placement) {
  uint64_t mask = 0;
  for (size_t j = 0; j < placement.size() && j < 64; ++j)
    if (!placement[j]) mask |= uint64_t(1) << j;
  return mask;
}

}  // namespace throng::anim
