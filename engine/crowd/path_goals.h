#pragma once
// Path-vector waypoints on the GPU: AgentPaths uploaded once, then GoalJob writes every
// agent's goal for a simulated second (shaders/path_goals.comp) into SteerBuffers::goals,
// where the steering pass reads it. The render path records it once per simulated second
// inside the frame, so no host copy races with frames in flight. CPU twin: writeGoals.
#include <string>
#include <vector>

#include "crowd/avoidance_jobs.h"
#include "crowd/path_vectors.h"

namespace throng::crowd {

struct PathBuffers {
  gpu::Buffer agentStart;   // per agent: start x, z, rotation cos, sin
  gpu::Buffer agentInfo;    // per agent: source, first second, last second, max speed (float bits)
  gpu::Buffer sourceRange;  // per source: first cumulative entry, vector count
  gpu::Buffer cumulative;   // every source's partial sums, one after another
  uint32_t count = 0;       // agents
};
// Throws Error for an empty source or an agent following a source that does not exist.
PathBuffers uploadPaths(const gpu::Context& context, const AgentPaths& paths);

struct GoalJob {
  const PathBuffers* paths = nullptr;    // input
  const SteerBuffers* agents = nullptr;  // output: goals
  uint32_t second = 0;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const;
};

}  // namespace throng::crowd
