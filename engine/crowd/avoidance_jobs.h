#pragma once
// The grid, steering and kinematic-advance passes as jobs (like synth/synth_jobs.h): named
// inputs and outputs, validate() listing what is missing or inconsistent, record() that
// checks and records. Per step: GridJob, barrier, AvoidanceJob, barrier, then either
// AdvanceJob (kinematic, `throng crowd`) or the synthesis RootMotionJob (render path), which
// moves each character along the heading the avoidance job wrote. CPU twins: avoidance.h.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "crowd/avoidance.h"
#include "crowd/crowd.h"
#include "gpu/program.h"
#include "gpu/timestamps.h"

namespace throng::crowd {

// The compiled passes. The steering pass is specialized per (policy, neighbour range), built
// on first use; subgroups of at least 4 lanes with vote, arithmetic and ballot are required
// (lavapipe: 8; every desktop GPU has them).
class AvoidancePrograms {
 public:
  explicit AvoidancePrograms(const gpu::Context& context);
  gpu::ComputeProgram count, scan, scatter, advance, goals;
  const gpu::ComputeProgram& steer(SteerPolicy policy, glm::ivec2 range) const;
  uint32_t chunk() const { return chunk_; }  // candidates shared per subgroup round

 private:
  const gpu::Context* context_;
  uint32_t chunk_ = 8;
  mutable std::map<std::tuple<uint32_t, int, int>, std::unique_ptr<gpu::ComputeProgram>> steer_;
};

// The grid's GPU arrays (Grid in avoidance.h), sized for up to `agentCapacity` agents.
struct GridBuffers {
  gpu::Buffer cellRank, counts, starts, sortedIndex, sorted;
  // What the passes read, as texels (lavapipe gathers texels, loops over lanes for
  // storage-buffer loads): `cellRank` as RG32UI, `counts` as RGBA32UI (four cells a texel),
  // `starts` and `sortedIndex` as R32UI, `sorted` as RGBA32F.
  gpu::Handle<VkBufferView> cellRankTexels, countTexels, startTexels, sortedIndexTexels,
      sortedTexels;
  uint32_t agentCapacity = 0;
  GridTable table;
  glm::vec2 cellSize{0.0f};  // x width, z depth (m)
};
GridBuffers makeGridBuffers(const gpu::Context& context, uint32_t agentCapacity,
                            glm::vec2 cellSize);

// Per-agent steering arrays beside CrowdBuffers: goal (target x, z, max speed, active) and
// steer (vx, vz, speed, flags).
struct SteerBuffers {
  gpu::Buffer goals;
  gpu::Buffer steer;
  // `goals` and `steer` as RGBA32F texels, for the steering pass and the grid build
  gpu::Handle<VkBufferView> goalTexels, steerTexels;
  uint32_t count = 0;
};
SteerBuffers uploadSteer(const gpu::Context& context, std::span<const glm::vec4> goals,
                         std::span<const glm::vec4> steer);

// Counting sort of the agents into the grid: clear, count (cell and rank per agent), scan,
// scatter of the agent index and a copy of (x, z, vx, vz). Barriers between its own passes.
struct GridJob {
  const CrowdBuffers* crowd = nullptr;   // input: placement
  const SteerBuffers* agents = nullptr;  // input: steer (velocities copied into the grid)
  const GridBuffers* grid = nullptr;     // output
  // Optional: a mark after the count, the scan and the scatter.
  gpu::TimestampPool* timestamps = nullptr;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const;
};

// Path-vector steering + avoidance: reads goals, the grid and each agent's previous velocity;
// writes placement.w (heading), steer and motion.z (wTarget).
struct AvoidanceJob {
  const CrowdBuffers* crowd = nullptr;   // input/output: placement (heading), motion (wTarget)
  const SteerBuffers* agents = nullptr;  // input: goals; input/output: steer
  const GridBuffers* grid = nullptr;     // input: built this step by GridJob
  AvoidanceParams params;
  SteerFrame frame;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const;
};

// position += velocity · dt for active agents (twin: advanceCpu).
struct AdvanceJob {
  const CrowdBuffers* crowd = nullptr;   // input/output: placement
  const SteerBuffers* agents = nullptr;  // input: steer, goals
  float dt = 0.0f;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const;
};

}  // namespace throng::crowd
