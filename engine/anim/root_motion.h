#pragma once
// How a character's root moves between frames (the paper's eq. 10 is in reference_synth.h and
// shaders/root_motion.comp): the heading rule of root motion, and speed changes over time. The
// root-motion pass (GPU and CPU twin) reads both; crowds choose them (crowd::Crowd::steering,
// synth::SpeedSchedule).
#include <cstdint>

#include <glm/glm.hpp>

namespace throng::anim {

// The heading rule: keep the heading (steered crowds set it themselves), or run around a
// circle centred at the origin.
enum class Steering : uint32_t { KeepHeading = 0, Circle = 1 };

// Heading that keeps a character on a circle around the origin (counter-clockwise).
float circleHeading(glm::vec2 position);

// Speed changes over time: at an epoch > 0 every character draws a new target speed weight in
// [lo, hi] (deterministic hash of character, epoch and seed), quantized to the motion cache's
// buckets when bucketWidth > 0; it takes effect at the end of the character's cycle.
struct SpeedRetarget {
  uint32_t epoch = 0;  // 0: no change this step
  uint32_t seed = 0;
  float lo = 0.0f, hi = 1.0f;
  float bucketWidth = 0.0f;
};
float retargetSpeed(uint32_t character, uint32_t epoch, uint32_t seed, float lo, float hi);
void applyRetarget(uint32_t character, const SpeedRetarget& retarget, glm::vec4& motion);

}  // namespace throng::anim
