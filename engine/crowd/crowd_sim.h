#pragma once
// Runs a crowd along its path vectors with avoidance at a fixed step and measures it
// (`throng crowd simulate|metrics`). Each step: grid, steering (policy), then a kinematic
// advance, position += velocity · dt, on the GPU (jobs) or the CPU twin.
//
// Why kinematic and not root motion (anim::stepCharacter): the only clip pair animated today
// runs at 2.5–4.5 m/s while the tracked people walk at 0.5–2 m/s, and w changes only when a
// cycle ends, so root motion would move agents at the clips' speeds instead of their path
// vectors' and the metrics would measure the clips, not the steering. The steering pass still
// writes heading and wTarget, which the render path hands to the root-motion pass.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "crowd/avoidance.h"
#include "crowd/crowd.h"
#include "crowd/crowd_metrics.h"
#include "crowd/obstacles.h"
#include "crowd/path_vectors.h"
#include "gpu/context.h"

namespace throng::crowd {

struct SimulationSetup {
  Crowd crowd;  // initial placement and motion (positions of agents not yet active are ignored)
  AgentPaths paths;  // one per agent
};

// Sees the crowd as the simulation goes (e.g. `--trajectories-out`). Frame f is the crowd at
// f · dt seconds: frame 0 before the first step, frame k + 1 after step k. Frames in which
// nobody is on the scene may be skipped (the simulation jumps to the next arrival), so `frame`
// can grow by more than one between calls.
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  // `placement`: every agent's (x, y, z, heading), parked far away when not active; `active`:
  // per agent, 1 when on the scene.
  virtual void observe(uint64_t frame, std::span<const glm::vec4> placement,
                       std::span<const uint8_t> active) = 0;
};

struct SimulationOptions {
  AvoidanceParams avoidance;
  float dt = 0.05f;                // must divide one second (1/dt steps per waypoint)
  float seconds = 20.0f;           // whole seconds simulated (rounded down, at least 1)
  float bodyRadius = kBodyRadius;  // collisions are counted at this radius (m); intrusions at
                                   // the avoidance's safe radius
  float slowSpeed = 0.0f;  // clip pair root speeds (speed → motion.z); 0, 0: leave motion.z
  float fastSpeed = 0.0f;
  StepObserver* observer = nullptr;  // optional, not owned
  // Optional static walls, not owned: both policies steer around them, and after each advance
  // the wall constraint keeps every agent off them (no crossing, never within the safe radius).
  const Obstacles* walls = nullptr;
};

// The binning of walls for a run: cells and reach of the sensing distance (the steering pass
// sees every segment within sensing; a step may move an agent up to sensing − radius).
WallGrid binWallsFor(const Obstacles& walls, const AvoidanceParams& avoidance);

struct SimulationResult {
  CrowdMetrics metrics;
  Crowd crowd;                   // final state
  std::vector<glm::vec4> steer;  // final velocities
  uint32_t steps = 0;
  double wallSeconds = 0.0;
};

// `context` null: the CPU twin; else the GPU jobs (one submit per step).
SimulationResult simulateCrowd(const gpu::Context* context, const SimulationSetup& setup,
                               const SimulationOptions& options);

// The per-second speeds the agents would have following their paths exactly over `seconds`
// (|waypoint(j) − waypoint(j−1)| over the seconds each is active): the reference of the KS.
std::vector<float> expectedSpeeds(const AgentPaths& paths, uint32_t seconds);

// A replay of the data: every source person is an agent, appearing at its own place and time.
// Throws Error naming `origin` (the trajectory file) when there is no source.
SimulationSetup replaySetup(std::span<const PathSource> sources,
                            std::string_view origin = "the trajectories");

}  // namespace throng::crowd
