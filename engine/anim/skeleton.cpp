#include "anim/skeleton.h"

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

}  // namespace throng::anim
