#pragma once
// Steering of a crowd on the GPU: agents follow their path vectors (waypoints once per simulated
// second) and avoid each other (uniform grid, then the avoidance policy), writing each agent's
// heading and speed weight into the crowd's buffers for the root-motion pass to take up. Used
// by storyboard crowds and the circle scene's lanes; the state of the simulated clock lives here.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "crowd/avoidance_jobs.h"
#include "crowd/nav_jobs.h"
#include "crowd/path_goals.h"

namespace throng::crowd {

// This step's steering: what changes from step to step and whether new waypoints are due.
struct SteerStep {
  SteerFrame frame;
  int64_t goalSecond = -1;  // ≥ 0: the waypoints of this second are computed first
};

class CrowdSteering {
 public:
  // `speeds`: per clip set its root speeds and the end of its agent range (speed → w).
  // Throws Error for inconsistent sizes or avoidance parameters.
  CrowdSteering(const gpu::Context& context, const AgentPaths& paths,
                const AvoidanceParams& avoidance, std::vector<ClipSpeeds> speeds);
  // Without path vectors: `count` agents that goals steer (setGoals).
  CrowdSteering(const gpu::Context& context, uint32_t count, const AvoidanceParams& avoidance,
                std::vector<ClipSpeeds> speeds);
  ~CrowdSteering();

  // Advances the simulated clock by dt and says what this step does.
  SteerStep advance(float dt);
  // Goals (when due), grid and avoidance over `crowd` (placement and motion are read and the
  // motion's speed weights written); barriers before and after.
  void record(VkCommandBuffer cmd, const CrowdBuffers& crowd, const SteerStep& step) const;

  // Static walls both policies steer around from the next step on (binned as binWallsFor in
  // crowd_sim.h); the render path keeps agents off them with WallConstraintJob over walls()
  // after root motion. Throws Error for invalid walls.
  void setWalls(const gpu::Context& context, const Obstacles& walls);
  const WallBuffers* walls() const { return walls_.get(); }  // null: none

  // Goals and navigation instead of path vectors (goals.h, nav_jobs.h): every agent's first goal
  // is chosen from `placement`, and each frame's steering follows its planned path.
  void setGoals(const gpu::Context& context, GoalScene goals, std::span<const glm::vec4> placement);
  // Between frames, with none in flight: the goals' state machines on read-back positions and
  // new plans (every N frames is enough: GoalSteering::update). Nothing without goals.
  void updateGoals(const gpu::Context& context, const CrowdBuffers& crowd);
  const GoalSteering* goals() const { return goals_.get(); }  // null: none
  const AvoidancePrograms& programs() const { return programs_; }

  double seconds() const { return time_; }
  uint32_t count() const { return count_; }
  const AvoidanceParams& avoidance() const { return avoidance_; }

 private:
  AvoidanceParams avoidance_;
  uint32_t count_ = 0;
  AvoidancePrograms programs_;
  SteerBuffers agents_;
  GridBuffers grid_;
  PathBuffers paths_;
  std::unique_ptr<WallBuffers> walls_;
  std::unique_ptr<GoalSteering> goals_;
  bool hasPaths_ = false;
  std::vector<ClipSpeeds> speeds_;
  double time_ = 0.0;
  uint32_t step_ = 0;
  int64_t goalSecond_ = -1;
};

}  // namespace throng::crowd
