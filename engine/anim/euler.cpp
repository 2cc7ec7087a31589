#include "anim/euler.h"

#include <cmath>

#include "anim/bvh_channels.h"
#include "core/error.h"
#include "core/math.h"

namespace throng::anim {

glm::vec4 axisRotation(Channel channel, float degrees) {
  if (!isRotation(channel)) return glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  // Half angle in double: BVH angles reach thousands of degrees on unwrapped captures.
  double half = 0.5 * double(degrees) * (3.14159265358979323846 / 180.0);
  glm::vec4 q(0.0f, 0.0f, 0.0f, float(std::cos(half)));
  q[channelAxis(channel)] = float(std::sin(half));
  return q;
}

glm::vec4 channelsToQuat(std::span<const Channel> channels, std::span<const float> values) {
  THRONG_CHECK(channels.size() == values.size(), "one value per channel");
  glm::vec4 q(0.0f, 0.0f, 0.0f, 1.0f);
  // Right-multiplying in listed order gives R = R1 * R2 * R3: the first is outermost.
  for (size_t i = 0; i < channels.size(); ++i) {
    if (isRotation(channels[i])) q = quatMul(q, axisRotation(channels[i], values[i]));
  }
  // Three float products drift from unit length by ~1e-7; renormalise so downstream slerp
  // and the motion textures see exact unit quaternions.
  return glm::normalize(q);
}

}  // namespace throng::anim
