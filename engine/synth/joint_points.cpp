#include "synth/joint_points.h"

#include <cmath>

#include "core/error.h"

namespace throng::synth {

JointMatrix jointMatrixAt(std::span<const JointPoint> character, std::span<const int32_t> parents,
                          size_t j) {
  const int32_t parent = parents[j];
  const glm::vec4 point = character[j].positionRadius;
  if (parent < 0) return gpu_types::boneMatrix(point, point, true);
  return gpu_types::boneMatrix(character[size_t(parent)].positionRadius, point, false);
}

std::vector<JointMatrix> jointMatrices(std::span<const JointPoint> points,
                                       std::span<const int32_t> parents) {
  const size_t joints = parents.size();
  THRONG_CHECK(joints > 0 && points.size() % joints == 0, "joint points (", points.size(),
               ") are not whole characters of ", joints, " joints");
  std::vector<JointMatrix> matrices(points.size());
  for (size_t first = 0; first < points.size(); first += joints)
    for (size_t j = 0; j < joints; ++j)
      matrices[first + j] = jointMatrixAt(points.subspan(first, joints), parents, j);
  return matrices;
}

glm::vec4 placeCachedPoint(glm::vec4 p, glm::vec4 place, float scale) {
  const float c = std::cos(place.w), s = std::sin(place.w);
  return glm::vec4(scale * glm::vec3(c * p.x + s * p.z, p.y, c * p.z - s * p.x) + glm::vec3(place),
                   scale * p.w);
}

}  // namespace throng::synth
