#include <doctest/doctest.h>

#include <cmath>

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
  std::vector<uint32_t> cellOf, counts, starts, sortedIndex;
  std::vector<glm::vec4> sorted;
};

GpuGrid buildOnGpu(const crowd::Crowd& c, const std::vector<glm::vec4>& steer, float cellSize) {
  gpu::Context& ctx = test::gpuContext();
  crowd::AvoidancePrograms programs(ctx);
  crowd::CrowdBuffers buffers = crowd::uploadCrowd(ctx, c);
  std::vector<glm::vec4> goals(c.size(), glm::vec4(0, 0, 1, 1));
  crowd::SteerBuffers agents = crowd::uploadSteer(ctx, goals, steer);
  crowd::GridBuffers grid = crowd::makeGridBuffers(ctx, uint32_t(c.size()), cellSize);
  crowd::GridJob job{&buffers, &agents, &grid};
  REQUIRE(job.validate().empty());
  // Twice, so leftovers of the first build (counts, cursors) would show.
  for (int k = 0; k < 2; ++k) gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) { job.record(cmd, programs); });
  GpuGrid g;
  const size_t n = c.size();
  g.cellOf = gpu::readback<uint32_t>(ctx, grid.cellOf, n);
  g.counts = gpu::readback<uint32_t>(ctx, grid.counts, grid.cellCount);
  g.starts = gpu::readback<uint32_t>(ctx, grid.starts, grid.cellCount);
  g.sortedIndex = gpu::readback<uint32_t>(ctx, grid.sortedIndex, n);
  g.sorted = gpu::readback<glm::vec4>(ctx, grid.sorted, n);
  CHECK(ctx.validationMessageCount() == 0);
  return g;
}

void compareGrids(uint32_t n, float cellSize) {
  crowd::Crowd c = gridCrowd(n, n);
  std::vector<glm::vec4> steer(n);
  for (uint32_t i = 0; i < n; ++i) steer[i] = glm::vec4(float(i), -float(i), 0, 0);
  crowd::Grid cpu = crowd::buildGridCpu(c.placement, steer, cellSize, crowd::gridCellCount(n));
  GpuGrid gpu = buildOnGpu(c, steer, cellSize);
  CHECK(gpu.cellOf == cpu.cellOf);
  CHECK(gpu.counts == cpu.counts);
  CHECK(gpu.starts == cpu.starts);
  CHECK(gpu.sortedIndex == cpu.sortedIndex);
  CHECK(gpu.sorted == cpu.sorted);
  // Invariants of a counting sort, checked on the CPU grid itself.
  uint32_t sum = 0, largest = 0;
  for (uint32_t cell = 0; cell < cpu.cellCount; ++cell) {
    REQUIRE(cpu.starts[cell] == sum);
    sum += cpu.counts[cell];
    largest = std::max(largest, cpu.counts[cell]);
    for (uint32_t k = cpu.starts[cell]; k < cpu.starts[cell] + cpu.counts[cell]; ++k) {
      REQUIRE(cpu.cellOf[cpu.sortedIndex[k]] == cell);
      if (k > cpu.starts[cell]) REQUIRE(cpu.sortedIndex[k] > cpu.sortedIndex[k - 1]);
    }
  }
  CHECK(sum == n);
  CHECK(largest > 4);  // the cluster fills some cells
  MESSAGE(n, " agents, ", cpu.cellCount, " hashed cells, largest cell ", largest);
}

}  // namespace

TEST_CASE("grid: table size is a power of two >= N within bounds") {
  CHECK(crowd::gridCellCount(0) == 1024);
  CHECK(crowd::gridCellCount(1024) == 1024);
  CHECK(crowd::gridCellCount(1025) == 2048);
  CHECK(crowd::gridCellCount(100000) == 131072);
  CHECK(crowd::gridCellCount(4000000) == crowd::kMaxGridCells);
}

TEST_CASE("grid: cell hash and random numbers are the shader's (fixed values)") {
  CHECK(crowd::pcgHash(0u) == 129708002u);
  CHECK(crowd::cellCoord({-0.1f, 2.9f}, 1.0f / 3.0f) == glm::ivec2(-1, 0));
  float u = crowd::steerRandom(5, 6, 7);
  CHECK(u >= 0.0f);
  CHECK(u < 1.0f);
  CHECK(u != crowd::steerRandom(5, 7, 7));
}

TEST_CASE("grid: GPU counting sort equals the CPU twin (counts, starts, sorted order), one scan block") {
  compareGrids(300, 3.0f);
}

TEST_CASE("grid: GPU counting sort equals the CPU twin over many scan blocks (100k agents)") {
  compareGrids(100000, 2.0f);
}
