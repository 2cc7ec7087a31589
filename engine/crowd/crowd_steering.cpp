#include "crowd/crowd_steering.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "crowd/crowd_sim.h"
#include "gpu/commands.h"

namespace throng::crowd {

CrowdSteering::CrowdSteering(const gpu::Context& context, const AgentPaths& paths,
                             const AvoidanceParams& avoidance, std::vector<ClipSpeeds> speeds)
    : CrowdSteering(context, uint32_t(paths.size()), avoidance, std::move(speeds)) {
  paths_ = uploadPaths(context, paths);
  hasPaths_ = true;
}

CrowdSteering::CrowdSteering(const gpu::Context& context, uint32_t count,
                             const AvoidanceParams& avoidance, std::vector<ClipSpeeds> speeds)
    : avoidance_(avoidance), count_(count), programs_(context), speeds_(std::move(speeds)) {
  if (count_ == 0) fail("steering needs at least one agent");
  const std::vector<std::string> problems = validateParams(avoidance_);
  if (!problems.empty()) fail("avoidance parameters: ", problems.front());
  if (speeds_.empty() || speeds_.back().end != count_)
    fail("steering: the clip sets' speed ranges must end at the ", count_, " agents");
  std::vector<glm::vec4> goals(count_, glm::vec4(0.0f)), steer(count_, glm::vec4(0.0f));
  agents_ = uploadSteer(context, goals, steer);
  grid_ = makeGridBuffers(context, count_, avoidance_.cellSize);
}

CrowdSteering::~CrowdSteering() = default;

void CrowdSteering::setGoals(const gpu::Context& context, GoalScene goals,
                             std::span<const glm::vec4> placement) {
  if (placement.size() != count_)
    fail("steering: goals for ", placement.size(), " agents, the crowd has ", count_);
  goals_ = std::make_unique<GoalSteering>(context, std::move(goals), placement);
}

void CrowdSteering::updateGoals(const gpu::Context& context, const CrowdBuffers& crowd) {
  if (goals_) goals_->update(context, crowd, time_);
}

void CrowdSteering::setWalls(const gpu::Context& context, const Obstacles& walls) {
  walls_ = std::make_unique<WallBuffers>(uploadWalls(context, binWallsFor(walls, avoidance_)));
}

SteerStep CrowdSteering::advance(float dt) {
  // The waypoint of second s is due at its end: steps inside it head for it with the time left.
  const int64_t second = int64_t(std::floor(time_));
  SteerStep s;
  s.frame.dt = dt;
  s.frame.secondsLeft = std::max(float(double(second + 1) - time_), 1e-3f);
  s.frame.step = step_++;
  s.frame.sets = speeds_;
  s.goalSecond = second != goalSecond_ ? second : -1;
  goalSecond_ = second;
  time_ += dt;
  return s;
}

void CrowdSteering::record(VkCommandBuffer cmd, const CrowdBuffers& crowd,
                           const SteerStep& step) const {
  if (crowd.count != count_) fail("steering: ", count_, " agents but the crowd has ", crowd.count);
  // The previous frame's synthesis wrote the state the grid reads.
  gpu::computeToComputeBarrier(cmd);
  SteerFrame frame = step.frame;
  if (goals_) {
    // Goals: each agent's next waypoint, at full speed (the waypoint is not due at a time).
    frame.secondsLeft = 1.0f;
    goals_->record(cmd, crowd, agents_, frame);
    gpu::computeToComputeBarrier(cmd);
  } else if (hasPaths_ && step.goalSecond >= 0) {
    GoalJob{&paths_, &agents_, uint32_t(step.goalSecond)}.record(cmd, programs_);
    gpu::computeToComputeBarrier(cmd);
  }
  GridJob{&crowd, &agents_, &grid_}.record(cmd, programs_);
  gpu::computeToComputeBarrier(cmd);
  AvoidanceJob{&crowd, &agents_, &grid_, avoidance_, frame, walls_.get()}.record(cmd, programs_);
  gpu::computeToComputeBarrier(cmd);
}

}  // namespace throng::crowd
