#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/rng.h"
#include "crowd/avoidance.h"
#include "crowd/avoidance_jobs.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"

using namespace throng;

namespace {

// Agents spread over a large area (negative coordinates too) with a dense cluster, so cells
// hold from 0 to dozens of agents and hashed buckets collide.
crowd::Crowd gridCrowd(uint32_t n, uint64_t seed) {
  crowd::Crowd c;
  c.resize(n);
  Rng rng(seed);
  for (uint32_t i = 0; i < n; ++i) {
    bool cluster = i % 5 == 0;
    float half = cluster ? 4.0f : 0.6f * std::sqrt(float(n));
    c.placement[i] = glm::vec4(rng.uniform(-half, half), 0.0f, rng.uniform(-half, half), 0.0f);
  }
  return c;
}

struct GpuGrid {
  std::vector<glm::uvec2> cellRank;
  std::vector<uint32_t> counts, starts, sortedIndex;
  std::vector<glm::vec4> sorted;
};

GpuGrid buildOnGpu(const crowd::Crowd& c, const std::vector<glm::vec4>& steer, glm::vec2 cellSize) {
  gpu::Context& ctx = test::gpuContext();
  crowd::AvoidancePrograms programs(ctx);
  crowd::CrowdBuffers buffers = crowd::uploadCrowd(ctx, c);
  std::vector<glm::vec4> goals(c.size(), glm::vec4(0, 0, 1, 1));
  crowd::SteerBuffers agents = crowd::uploadSteer(ctx, goals, steer);
  crowd::GridBuffers grid = crowd::makeGridBuffers(ctx, uint32_t(c.size()), cellSize);
  crowd::GridJob job{&buffers, &agents, &grid};
  REQUIRE(job.validate().empty());
  // Twice, so leftovers of the first build (counts) would show.
  for (int k = 0; k < 2; ++k)
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) { job.record(cmd, programs); });
  GpuGrid g;
  const size_t n = c.size();
  g.cellRank = gpu::readback<glm::uvec2>(ctx, grid.cellRank, n);
  g.counts = gpu::readback<uint32_t>(ctx, grid.counts, grid.table.cellCount);
  g.starts = gpu::readback<uint32_t>(ctx, grid.starts, grid.table.cellCount + 1);
  g.sortedIndex = gpu::readback<uint32_t>(ctx, grid.sortedIndex, n);
  g.sorted = gpu::readback<glm::vec4>(ctx, grid.sorted, n);
  CHECK(ctx.validationMessageCount() == 0);
  return g;
}

void compareGrids(uint32_t n, glm::vec2 cellSize) {
  crowd::Crowd c = gridCrowd(n, n);
  std::vector<glm::vec4> steer(n);
  for (uint32_t i = 0; i < n; ++i) steer[i] = glm::vec4(float(i), -float(i), 0, 0);
  crowd::Grid cpu = crowd::buildGridCpu(c.placement, steer, cellSize, crowd::gridTable(n));
  GpuGrid gpu = buildOnGpu(c, steer, cellSize);
  CHECK(gpu.counts == cpu.counts);
  CHECK(gpu.starts == cpu.starts);
  // The GPU's order within a cell is its atomics' order: each agent sits in its own cell's
  // range, at its rank there, once, with its own copy of position and velocity.
  std::vector<int> seen(n, 0);
  bool cellsMatch = true, ranksMatch = true, copiesMatch = true;
  for (uint32_t i = 0; i < n; ++i) {
    cellsMatch = cellsMatch && gpu.cellRank[i].x == cpu.cellOf[i];
    ranksMatch = ranksMatch && gpu.cellRank[i].y < cpu.counts[cpu.cellOf[i]];
  }
  for (uint32_t k = 0; k < n; ++k) {
    uint32_t i = gpu.sortedIndex[k];
    REQUIRE(i < n);
    ++seen[i];
    uint32_t cell = cpu.cellOf[i];
    cellsMatch = cellsMatch && k >= cpu.starts[cell] && k < cpu.starts[cell + 1] &&
                 k == cpu.starts[cell] + gpu.cellRank[i].y;
    copiesMatch = copiesMatch && gpu.sorted[k] == glm::vec4(c.placement[i].x, c.placement[i].z,
                                                            steer[i].x, steer[i].y);
  }
  CHECK(cellsMatch);
  CHECK(ranksMatch);
  CHECK(copiesMatch);
  CHECK(std::count(seen.begin(), seen.end(), 1) == int(n));
  // Invariants of a counting sort, checked on the CPU grid itself.
  uint32_t sum = 0, largest = 0;
  for (uint32_t cell = 0; cell < cpu.table.cellCount; ++cell) {
    REQUIRE(cpu.starts[cell] == sum);
    sum += cpu.counts[cell];
    largest = std::max(largest, cpu.counts[cell]);
    for (uint32_t k = cpu.starts[cell]; k < cpu.starts[cell + 1]; ++k)
      REQUIRE(cpu.cellOf[cpu.sortedIndex[k]] == cell);
  }
  CHECK(sum == n);
  CHECK(cpu.starts[cpu.table.cellCount] == n);
  CHECK(largest > 4);  // the cluster fills some cells
  MESSAGE(n, " agents, ", cpu.table.cellCount, " cells (", 1u << cpu.table.widthShift, " x ",
          cpu.table.rowMask + 1, "), largest cell ", largest);
}

}  // namespace

TEST_CASE(
    "grid: the table is a power of two >= N within bounds, at least 32 x 32, rows <= columns") {
  CHECK(crowd::gridTable(0).cellCount == 1024);
  CHECK(crowd::gridTable(1024).cellCount == 1024);
  CHECK(crowd::gridTable(1025).cellCount == 2048);
  CHECK(crowd::gridTable(100000).cellCount == 131072);
  CHECK(crowd::gridTable(4000000).cellCount == crowd::kMaxGridCells);
  for (uint32_t n : {0u, 1025u, 100000u, 4000000u}) {
    crowd::GridTable t = crowd::gridTable(n);
    CHECK(t.cellCount == (t.rowMask + 1) << t.widthShift);
    CHECK((t.rowMask & (t.rowMask + 1)) == 0);
    CHECK(t.rowMask + 1 >= 32);
    CHECK(t.rowMask + 1 <= 1u << t.widthShift);
  }
}

TEST_CASE("grid: cell index, hash and random numbers are the shader's (fixed values)") {
  CHECK(crowd::pcgHash(0u) == 129708002u);
  CHECK(crowd::cellCoord({-0.1f, 2.9f}, glm::vec2(1.0f / 3.0f)) == glm::ivec2(-1, 0));
  CHECK(crowd::cellCoord({1.6f, 2.9f}, glm::vec2(1.0f / 1.5f, 1.0f / 3.0f)) == glm::ivec2(1, 0));
  crowd::GridTable t{1024, 5, 31};
  CHECK(crowd::cellIndex({0, 0}, t) == 0u);
  CHECK(crowd::cellIndex({1, 0}, t) == 1u);
  CHECK(crowd::cellIndex({0, 1}, t) == 32u);
  CHECK(crowd::cellIndex({-1, 0}, t) == 31u);   // columns wrap
  CHECK(crowd::cellIndex({0, -1}, t) == 992u);  // rows wrap
  CHECK(crowd::cellIndex({32, 33}, t) == 32u);  // a table apart: the same cell
  float u = crowd::steerRandom(5, 6, 7);
  CHECK(u >= 0.0f);
  CHECK(u < 1.0f);
  CHECK(u != crowd::steerRandom(5, 7, 7));
}

TEST_CASE(
    "grid: GPU counting sort equals the CPU twin (counts, starts, each agent in its cell), small "
    "crowd") {
  compareGrids(300, glm::vec2(3.0f));
  compareGrids(300, glm::vec2(1.5f, 3.0f));
}

TEST_CASE("grid: GPU counting sort equals the CPU twin on 100k agents") {
  compareGrids(100000, glm::vec2(1.5f, 3.0f));
}

TEST_CASE("grid: gridOrder numbers agents in the grid's slot order, stably within a cell") {
  const uint32_t n = 5000;
  crowd::Crowd c = gridCrowd(n, 11);
  const glm::vec2 cellSize(1.5f, 3.0f);
  const crowd::GridTable table = crowd::gridTable(n);
  const std::vector<uint32_t> order = crowd::gridOrder(c.placement, cellSize, table);
  REQUIRE(order.size() == n);
  std::vector<uint32_t> sortedCopy = order;
  std::sort(sortedCopy.begin(), sortedCopy.end());
  for (uint32_t k = 0; k < n; ++k) REQUIRE(sortedCopy[k] == k);  // a permutation
  // The order is the CPU grid's slot order: by cell, and by agent index within a cell.
  std::vector<glm::vec4> steer(n, glm::vec4(0.0f));
  crowd::Grid grid = crowd::buildGridCpu(c.placement, steer, cellSize, table);
  CHECK(order == grid.sortedIndex);
  // Renumbered so, the crowd's own grid is the identity.
  std::vector<glm::vec4> renumbered(n);
  for (uint32_t k = 0; k < n; ++k) renumbered[k] = c.placement[order[k]];
  crowd::Grid again = crowd::buildGridCpu(renumbered, steer, cellSize, table);
  for (uint32_t k = 0; k < n; ++k) REQUIRE(again.sortedIndex[k] == k);
  CHECK_THROWS_AS(crowd::gridOrder(c.placement, glm::vec2(0.0f, 3.0f), table), Error);
}
