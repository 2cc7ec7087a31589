#pragma once
// Goals and navigation on the GPU (docs/design.md, "Goals and navigation"). The CPU plans
// (goals.h, nav_mesh.h) when an agent's goal changes; every frame NavFollowJob
// (shaders/nav_follow.comp) advances each agent along its waypoints and writes its steering goal
// into SteerBuffers::goals for the avoidance pass. CPU twin: navFollowCpu.
//
// GoalSteering owns it all for one crowd. Per frame, with no other goal pass (GoalJob) in it:
//
//   GoalSteering goals(context, scene, crowd.placement);     // chooses goals, plans, uploads
//   ...                                                      // each frame:
//   goals.record(cmd, crowdBuffers, steerBuffers, frame);    // then GridJob, AvoidanceJob, ...
//   ...                                                      // every N frames, between frames:
//   goals.update(context, crowdBuffers, seconds);            // reads back, transitions, replans
//   if (goals.allDone()) ...                                 // "run to the end state"
#include <span>
#include <string>
#include <vector>

#include "crowd/avoidance_jobs.h"
#include "crowd/goals.h"
#include "gpu/program.h"
#include "shaders/nav_types.h"

namespace throng::crowd {

using gpu_types::NavFollowPush;
static_assert(sizeof(NavFollowPush) == 16, "NavFollowPush must match the GLSL push block");

// Every agent's path in one array (CSR): per agent (first waypoint, count, max speed bits, 0);
// a path's first waypoint is where it was planned from. Count 0: no goal (steering goal inactive).
struct NavPaths {
  std::vector<glm::uvec4> agentPath;
  std::vector<glm::vec2> waypoints;
};
// Throws Error when the sizes differ or a path has a single point.
NavPaths packPaths(const std::vector<std::vector<glm::vec2>>& paths,
                   std::span<const float> maxSpeed);

struct NavBuffers {
  gpu::Buffer agentPath;  // glm::uvec4 per agent
  gpu::Buffer waypoints;  // glm::vec2 each (capacity may exceed waypointCount)
  gpu::Buffer progress;   // uint32 per agent: the waypoint headed for
  uint32_t count = 0;     // agents
  uint32_t waypointCount = 0;
};
// Every agent starts at waypoint 1.
NavBuffers uploadNav(const gpu::Context& context, const NavPaths& paths);
// Replaces the paths (growing the waypoint buffer when needed) and restarts `changed` agents at
// waypoint 1; the others keep their progress. Host copies: no frame in flight may use `buffers`.
void updateNav(const gpu::Context& context, NavBuffers& buffers, const NavPaths& paths,
               std::span<const uint32_t> changed);

class NavPrograms {
 public:
  explicit NavPrograms(const gpu::Context& context);
  gpu::ComputeProgram follow;
};

struct NavFollowJob {
  const CrowdBuffers* crowd = nullptr;   // input: placement
  const NavBuffers* nav = nullptr;       // input: paths, waypoints; input/output: progress
  const SteerBuffers* agents = nullptr;  // output: goals
  float reach = 0.5f;                    // waypoints nearer than this are passed (m)
  float secondsLeft = 1.0f;              // the avoidance pass's (SteerFrame::secondsLeft)

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const NavPrograms& programs) const;
};

// The twin of nav_follow.comp: placement (x, y, z, heading) in, progress updated, goals written.
void navFollowCpu(std::span<const glm::vec4> placement, const NavPaths& paths,
                  std::span<uint32_t> progress, float reach, float secondsLeft,
                  std::span<glm::vec4> goals);

// Goals, state machines, planner and path buffers of one crowd.
class GoalSteering {
 public:
  // Chooses every agent's first goal from where it stands (`placement`, the crowd's
  // (x, y, z, heading)), plans and uploads. Throws Error for an invalid scene (goals.h).
  GoalSteering(const gpu::Context& context, GoalScene scene, std::span<const glm::vec4> placement);

  // Host side, when no frame in flight uses the crowd or these buffers: reads the placement and
  // each agent's waypoint back, runs the state machines at `seconds` (the simulated clock), plans
  // the agents whose goal changed or that are stuck (GoalScene::stuckSeconds) and uploads their
  // paths. Every N frames is enough: arrivals and timers are
  // seen up to N frames late (once per simulated second is fine for whole-second waits).
  void update(const gpu::Context& context, const CrowdBuffers& crowd, double seconds);
  // Records NavFollowJob over the crowd (barrier before: the previous frame moved it): each
  // agent's waypoint advanced and its goal written into `steer.goals`. `frame.secondsLeft` is
  // the value the avoidance pass after it uses (a constant such as 1 s suits goals).
  void record(VkCommandBuffer cmd, const CrowdBuffers& crowd, const SteerBuffers& steer,
              const SteerFrame& frame) const;

  uint32_t count() const { return uint32_t(machine_.agents().size()); }
  uint32_t agentsAtGoal() const { return machine_.agentsAtGoal(); }  // done: final state reached
  bool allDone() const { return machine_.allDone(); }
  const GoalMachine& machine() const { return machine_; }
  const NavBuffers& buffers() const { return nav_; }

 private:
  GoalMachine machine_;
  NavPrograms programs_;
  NavBuffers nav_;
  std::vector<float> maxSpeed_;
};

}  // namespace throng::crowd
