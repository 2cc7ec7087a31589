#pragma once
// The circle scene (paper Fig. 9) steered like a storyboard crowd: each runner follows its own
// lane circle as path-vector waypoints, one chord per second, with collision avoidance.
// Re-aiming every runner at the tangent of where it stands (Steering::Circle) spirals outward,
// since every straight step leaves the circle (≈ +0.9 m mean radius in 60 s), and ignores the
// others; waypoints on the lane pull runners back to it and the avoidance pass keeps them apart.
// The waypoints are ordinary AgentPaths, so the GPU path (GoalJob, GridJob, AvoidanceJob,
// then root motion with Steering::KeepHeading) and its CPU twin below need nothing new.
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

#include "anim/motion_texture.h"
#include "anim/reference_synth.h"
#include "crowd/avoidance.h"
#include "crowd/crowd.h"
#include "crowd/path_vectors.h"

namespace throng::crowd {

// One circle per runner through its start, centred at the origin, run counter-clockwise (the
// direction of anim::circleHeading) at the clip pair's root speed for its w (motion.y): a lap
// takes a whole number of seconds n = round(2πr / speed) so the waypoints repeat exactly each
// lap. Runners on one lane with the same n share one source. Max speed: 1.25 × the lap speed.
// Throws Error for a runner at the centre or root speeds that are not positive.
AgentPaths circlePaths(const Crowd& crowd, float slowSpeed, float fastSpeed);

// Pairs of runners closer than `distance` (m) on the ground plane.
uint32_t countClosePairs(std::span<const glm::vec4> placement, float distance);

// The steered crowd's motion on the CPU, one step at a time: the twin of the GPU frame's steering
// (goals once per second, grid, avoidance) followed by root motion keeping the heading it set.
// With no paths, root motion alone with the crowd's own steering.
class SteeredCrowdCpu {
 public:
  SteeredCrowdCpu(const anim::MotionPair& pair, Crowd crowd, const AgentPaths* paths,
                  const AvoidanceParams& params);
  // `retarget`: the speed change this step applies (as the crowd's speed schedule gives it).
  void step(float dt, const anim::SpeedRetarget& retarget = {});
  const Crowd& crowd() const { return crowd_; }

 private:
  const anim::MotionPair& pair_;
  Crowd crowd_;
  const AgentPaths* paths_;
  AvoidanceParams params_;
  std::vector<glm::vec4> goals_, steer_;
  SteerFrame frame_;
  double time_ = 0.0;
  uint32_t steps_ = 0;
  int64_t goalSecond_ = -1;
};

struct CircleRunFigures {
  double meanRadiusDrift = 0.0;     // mean over runners of |p(end)| − |p(start)| (m)
  double meanAbsRadiusError = 0.0;  // mean over runners of | |p(end)| − |p(start)| | (m)
  uint32_t minClosePairs = 0;       // pairs closer than 0.6 m, fewest and most over the frames
  uint32_t maxClosePairs = 0;
  double meanClosePairs = 0.0;
};

// The render path's motion on the CPU, `seconds` at step `dt`: with `paths` null, root motion
// with the crowd's own steering (Steering::Circle re-aims at the tangent); else the twin of the
// steered frame (goals once per second, grid, steerCpu, then root motion keeping the heading).
CircleRunFigures runCircleCpu(const anim::MotionPair& pair, Crowd crowd, const AgentPaths* paths,
                              const AvoidanceParams& params, float dt, float seconds);

}  // namespace throng::crowd
