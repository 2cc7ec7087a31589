#include "crowd/avoidance_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "core/rng.h"
#include "crowd/avoidance_jobs.h"
#include "crowd/crowd_sim.h"
#include "gpu/commands.h"
#include "gpu/timestamps.h"

namespace throng::crowd {
namespace {
double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

SteerFrame benchFrame(int s) {
  SteerFrame frame;
  frame.dt = 0.05f;
  frame.secondsLeft = 1.0f - 0.05f * float(s % 20);
  frame.step = uint32_t(s);
  return frame;
}

// The CPU twin (one thread) over the same steps from the same start: grid + steering, median ms.
double cpuTwinStepMs(std::vector<glm::vec4> placement, std::vector<glm::vec4> steer,
                     const std::vector<glm::vec4>& goals, const GridTable& table,
                     const AvoidanceParams& params, int steps, int warmup, const WallGrid* walls) {
  std::vector<glm::vec4> motion(placement.size(), glm::vec4(0.0f));
  std::vector<double> ms;
  for (int s = 0; s < warmup + steps; ++s) {
    SteerFrame frame = benchFrame(s);
    auto begin = std::chrono::steady_clock::now();
    Grid grid = buildGridCpu(placement, steer, params.cellSize, table);
    steerCpu(grid, params, frame, placement, motion, goals, steer, walls);
    auto end = std::chrono::steady_clock::now();
    if (s >= warmup) ms.push_back(std::chrono::duration<double, std::milli>(end - begin).count());
    const std::vector<glm::vec4> previous = placement;
    advanceCpu(placement, steer, goals, frame.dt);
    if (walls)
      wallConstraintCpu(*walls, params.radius, previous, placement, 0, uint32_t(placement.size()));
  }
  return median(ms);
}
bool nearBox(glm::vec2 p, float half) {
  const glm::vec2 local = glm::mod(p + half, 10.0f) - 5.0f;
  return std::abs(local.x) < 1.5f && std::abs(local.y) < 1.5f;
}
}  // namespace

Obstacles benchBoxes(float half) {
  Obstacles o;
  for (float x = -half + 5.0f; x < half; x += 10.0f)
    for (float z = -half + 5.0f; z < half; z += 10.0f) {
      const glm::vec2 box[] = {
          {x - 1.0f, z - 1.0f}, {x + 1.0f, z - 1.0f}, {x + 1.0f, z + 1.0f}, {x - 1.0f, z + 1.0f}};
      o.addPolyline(box, true);
    }
  return o;
}

AvoidanceTiming benchmarkAvoidance(const gpu::Context& context, uint32_t agents,
                                   const AvoidanceParams& params, int steps, float density,
                                   BenchNumbering numbering, bool walls) {
  if (agents == 0 || steps < 1 || !(density > 0.0f))
    fail("benchmark needs agents, steps and a positive density");
  Crowd crowd;
  crowd.resize(agents);
  std::vector<glm::vec4> goals(agents), steer(agents);
  Rng rng(7);
  const float half = 0.5f * std::sqrt(float(agents) / density);
  for (uint32_t i = 0; i < agents; ++i) {
    glm::vec2 p(rng.uniform(-half, half), rng.uniform(-half, half));
    while (walls && nearBox(p, half)) p = {rng.uniform(-half, half), rng.uniform(-half, half)};
    float heading = rng.uniform(-kPi, kPi);
    glm::vec2 dir(std::sin(heading), std::cos(heading));
    crowd.placement[i] = glm::vec4(p.x, 0.0f, p.y, heading);
    goals[i] = glm::vec4(p + 1.3f * dir, 2.0f, 1.0f);
    steer[i] = glm::vec4(1.3f * dir, 1.3f, 0.0f);
  }
  if (numbering == BenchNumbering::Grid) {
    const std::vector<uint32_t> order =
        gridOrder(crowd.placement, params.cellSize, gridTable(agents));
    std::vector<glm::vec4> placement(agents), goalsInOrder(agents), steerInOrder(agents);
    for (uint32_t k = 0; k < agents; ++k) {
      placement[k] = crowd.placement[order[k]];
      goalsInOrder[k] = goals[order[k]];
      steerInOrder[k] = steer[order[k]];
    }
    crowd.placement = std::move(placement);
    goals = std::move(goalsInOrder);
    steer = std::move(steerInOrder);
  }
  const std::vector<glm::vec4> startPlacement = crowd.placement, startSteer = steer;
  std::optional<WallGrid> wallGrid;
  std::unique_ptr<WallBuffers> wallBuffers;
  if (walls) {
    wallGrid = binWallsFor(benchBoxes(half), params);
    wallBuffers = std::make_unique<WallBuffers>(uploadWalls(context, *wallGrid));
  }
  AvoidancePrograms programs(context);
  CrowdBuffers buffers = uploadCrowd(context, crowd);
  SteerBuffers agentBuffers = uploadSteer(context, goals, steer);
  GridBuffers grid = makeGridBuffers(context, agents, params.cellSize);
  gpu::CommandPool pool(context);
  VkCommandBuffer cmd = pool.allocate();
  gpu::Fence fence(context);
  gpu::TimestampPool timestamps(context, 6);
  std::vector<double> countMs, scanMs, scatterMs, gridMs, steerMs, totalMs, moveMs;
  const int warmup = 2;
  for (int s = 0; s < warmup + steps; ++s) {
    SteerFrame frame = benchFrame(s);
    GridJob gridJob{&buffers, &agentBuffers, &grid, &timestamps};
    AvoidanceJob avoid{&buffers, &agentBuffers, &grid, params, frame, wallBuffers.get()};
    // With walls the advance constrains the move in the same pass (as `throng crowd` runs).
    AdvanceJob advance{&buffers, &agentBuffers, frame.dt, wallBuffers.get(), params.radius};
    timestamps.reset();
    gpu::beginCommands(cmd);
    timestamps.write(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);  // 0
    gridJob.record(cmd, programs);                             // 1, 2, 3
    gpu::computeToComputeBarrier(cmd);
    avoid.record(cmd, programs);
    timestamps.write(cmd);  // 4
    gpu::computeToComputeBarrier(cmd);
    advance.record(cmd, programs);
    timestamps.write(cmd);  // 5
    gpu::endCommands(cmd);
    gpu::submit(context, cmd, fence.get());
    fence.wait();
    fence.reset();
    if (s < warmup) continue;
    std::vector<uint64_t> ticks = timestamps.fetch();
    countMs.push_back(timestamps.millisecondsBetween(ticks, 0, 1));
    scanMs.push_back(timestamps.millisecondsBetween(ticks, 1, 2));
    scatterMs.push_back(timestamps.millisecondsBetween(ticks, 2, 3));
    gridMs.push_back(timestamps.millisecondsBetween(ticks, 0, 3));
    steerMs.push_back(timestamps.millisecondsBetween(ticks, 3, 4));
    totalMs.push_back(timestamps.millisecondsBetween(ticks, 0, 4));
    moveMs.push_back(timestamps.millisecondsBetween(ticks, 4, 5));
  }
  AvoidanceTiming t;
  t.cpuMs = cpuTwinStepMs(startPlacement, startSteer, goals, grid.table, params, steps, warmup,
                          wallGrid ? &*wallGrid : nullptr);
  t.moveMs = median(moveMs);
  t.wallSegments = wallGrid ? uint32_t(wallGrid->segments.size()) : 0u;
  t.agents = agents;
  t.gridMs = median(gridMs);
  t.countMs = median(countMs);
  t.scanMs = median(scanMs);
  t.scatterMs = median(scatterMs);
  t.steerMs = median(steerMs);
  t.totalMs = median(totalMs);
  t.steps = steps;
  return t;
}

}  // namespace throng::crowd
