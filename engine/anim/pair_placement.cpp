#include "anim/pair_placement.h"

#include <algorithm>

#include "anim/reference_synth.h"

namespace throng::anim {

std::vector<bool> placementJoints(const MotionPair& pair) {
  const int n = pair.jointCount();
  if (n < 1 || pair.slow.frameCount < 1 || int(pair.parents.size()) != n)
    return std::vector<bool>(size_t(std::max(n, 0)), false);
  std::vector<PoseJoint> pose(static_cast<size_t>(n));
  poseCharacterSpace(pair, 0.0f, 0.0f, pose);
  std::vector<glm::vec3> positions;
  for (const PoseJoint& joint : pose) positions.push_back(joint.position);
  return placementJoints(pair.parents, positions);
}

}  // namespace throng::anim
