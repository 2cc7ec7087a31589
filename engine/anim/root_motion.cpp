#include "anim/root_motion.h"

#include <cmath>

#include "anim/speed_buckets.h"
#include "shaders/shared_types.h"

namespace throng::anim {

float retargetSpeed(uint32_t character, uint32_t epoch, uint32_t seed, float lo, float hi) {
  uint32_t h = character * 747796405u + epoch * 2891336453u + seed * 1181783497u + 12345u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  h = (h >> 22u) ^ h;
  return lo + (hi - lo) * float(h >> 8) * (1.0f / 16777216.0f);
}

void applyRetarget(uint32_t character, const SpeedRetarget& r, glm::vec4& motion) {
  if (r.epoch == 0) return;
  float target = retargetSpeed(character, r.epoch, r.seed, r.lo, r.hi);
  motion = gpu_types::withTargetSpeedWeight(
      motion, r.bucketWidth > 0.0f ? quantizeSpeed(target, r.bucketWidth) : target);
}

float circleHeading(glm::vec2 p) {
  // Counter-clockwise tangent (-z, x) seen from above; heading θ faces (sin θ, cos θ).
  return std::atan2(-p.y, p.x);
}

}  // namespace throng::anim
