// The density-dependent speed of the steering pass (shaders/crowd_types.h): Weidmann's
// fundamental diagram over the kernel density ahead, the same on the GPU and in the CPU twin.
#include <doctest/doctest.h>

#include <cmath>

#include "crowd/avoidance.h"
#include "crowd/avoidance_jobs.h"
#include "crowd/crowd.h"
#include "crowd/crowd_sim.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "shaders/crowd_types.h"

using namespace throng;

namespace {

float weidmann(float rho) {
  return 1.0f - std::exp(-gpu_types::kWeidmannGamma *
                         (1.0f / rho - 1.0f / gpu_types::kWeidmannMaxDensity));
}

// The summed fixed-point weight that reads as `rho` persons/m².
uint32_t weightsFor(float rho, float norm) {
  return uint32_t(std::lround(rho / norm * gpu_types::kDensityScale));
}

// A block of `side` × `side` agents `spacing` apart, all walking at 1.3 m/s towards waypoints
// 1.3 m ahead (preferred speed 1.3 m/s, the most they may walk), and one agent alone far away.
// They walk 0.3 rad off the lattice's rows, so no row lies exactly on the edge of the half disc
// ahead (a crowd's neighbours lie anywhere; a lattice row on that edge would all be left out).
struct Block {
  crowd::Crowd crowd;
  std::vector<glm::vec4> goals, steer;
};
Block walkingBlock(int side, float spacing) {
  Block b;
  const auto n = uint32_t(side * side + 1);
  b.crowd.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    const glm::vec2 p = i + 1 == n ? glm::vec2(100.0f, 100.0f)
                                   : glm::vec2(float(i % side), float(i / side)) * spacing;
    b.crowd.placement[i] = glm::vec4(p.x, 0.0f, p.y, 0.0f);
    const glm::vec2 dir(std::sin(0.3f), std::cos(0.3f));
    b.goals.push_back(glm::vec4(p + 1.3f * dir, 1.3f, 1.0f));
    b.steer.push_back(glm::vec4(1.3f * dir, 1.3f, 0.0f));
  }
  return b;
}

}  // namespace

TEST_CASE("density speed: Weidmann's diagram, floored, in steps of 1/1024") {
  crowd::AvoidanceParams params;
  const float norm = crowd::densityPush(params).y;
  CHECK(norm == doctest::Approx(6.0f / (3.14159265f * 1.5f * 1.5f)));
  CHECK(crowd::densitySpeedFactor(0, norm) == 1.0f);
  for (float rho : {0.5f, 1.0f, 2.0f, 3.0f, 4.0f}) {
    CAPTURE(rho);
    CHECK(crowd::densitySpeedFactor(weightsFor(rho, norm), norm) ==
          doctest::Approx(std::max(weidmann(rho), gpu_types::kDensityMinSpeed)).epsilon(0.002));
  }
  // Packed beyond the diagram's jam density: the floor, so a jam still creeps.
  CHECK(crowd::densitySpeedFactor(weightsFor(8.0f, norm), norm) == gpu_types::kDensityMinSpeed);
  // Off: no weight reads as a density.
  params.densityRadius = 0.0f;
  CHECK(crowd::densityPush(params) == glm::vec2(0.0f));
  CHECK(crowd::densitySpeedFactor(123456, 0.0f) == 1.0f);
}

TEST_CASE(
    "density speed: only neighbours ahead and within the radius weigh, the agent itself not") {
  const float inv = 1.0f / (1.5f * 1.5f);
  const glm::vec2 dir(0.0f, 1.0f);
  auto weight = [&](glm::vec2 other) {
    const glm::vec2 x = -other;  // own position (origin) − the other's
    return crowd::densityWeight(x, glm::dot(x, x), dir, inv);
  };
  CHECK(weight({0.0f, 0.0f}) == 0u);
  CHECK(weight({0.0f, 1.0f}) > 0u);    // ahead
  CHECK(weight({0.0f, -1.0f}) == 0u);  // behind
  CHECK(weight({1.0f, 0.0f}) == 0u);   // abreast: the half disc ahead is open
  CHECK(weight({0.0f, 1.6f}) == 0u);   // beyond R
  CHECK(weight({0.3f, 0.5f}) > weight({0.3f, 1.0f}));
  // On a square lattice of known density the half-disc kernel reads about that density.
  for (float spacing : {0.6f, 0.8f, 1.0f}) {
    CAPTURE(spacing);
    uint32_t sum = 0;
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j) sum += weight(glm::vec2(float(i), float(j) + 0.5f) * spacing);
    crowd::AvoidanceParams params;
    const float rho = float(sum) / gpu_types::kDensityScale * crowd::densityPush(params).y;
    CHECK(rho == doctest::Approx(1.0f / (spacing * spacing)).epsilon(0.12));
  }
}

TEST_CASE("density speed: a dense block walks slower than an agent alone, GPU as the twin") {
  gpu::Context& ctx = test::gpuContext();
  for (crowd::SteerPolicy policy : {crowd::SteerPolicy::Ttc, crowd::SteerPolicy::Rule}) {
    CAPTURE(crowd::steerPolicyName(policy));
    crowd::AvoidanceParams params;
    params.policy = policy;
    Block cpu = walkingBlock(12, 0.65f);  // 2.4 persons/m²: Weidmann allows 0.42 of the speed
    const auto n = uint32_t(cpu.crowd.size());
    crowd::AvoidancePrograms programs(ctx);
    crowd::CrowdBuffers buffers = crowd::uploadCrowd(ctx, cpu.crowd);
    crowd::SteerBuffers agents = crowd::uploadSteer(ctx, cpu.goals, cpu.steer);
    crowd::GridBuffers grid = crowd::makeGridBuffers(ctx, n, params.cellSize);
    const crowd::SteerFrame frame{0.05f, 1.0f, 0, 1.0f, 3.0f, {}};
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      crowd::GridJob{&buffers, &agents, &grid}.record(cmd, programs);
      gpu::computeToComputeBarrier(cmd);
      crowd::AvoidanceJob{&buffers, &agents, &grid, params, frame}.record(cmd, programs);
    });
    const crowd::Grid g =
        crowd::buildGridCpu(cpu.crowd.placement, cpu.steer, params.cellSize, crowd::gridTable(n));
    crowd::steerCpu(g, params, frame, cpu.crowd.placement, cpu.crowd.motion, cpu.goals, cpu.steer);
    const std::vector<glm::vec4> steer = gpu::readback<glm::vec4>(ctx, agents.steer, n);
    float worst = 0.0f;
    for (uint32_t i = 0; i < n; ++i)
      worst = std::max(worst, glm::length(glm::vec2(steer[i]) - glm::vec2(cpu.steer[i])));
    CHECK(worst <= 1e-4f);
    // The rule takes the capped speed at once, TTC relaxes towards it (ξ = 0.54 s): after one
    // step of 0.05 s an agent in the middle of the block has slowed, the lone one has not.
    const uint32_t middle = 6 * 12 + 6;
    MESSAGE(crowd::steerPolicyName(policy), ": middle of the block ", cpu.steer[middle].z,
            " m/s, alone ", cpu.steer[n - 1].z, " m/s");
    CHECK(cpu.steer[n - 1].z == doctest::Approx(1.3f));
    if (policy == crowd::SteerPolicy::Rule)
      CHECK(cpu.steer[middle].z < 0.6f * 1.3f);
    else
      CHECK(cpu.steer[middle].z < 1.3f - 0.04f);
  }
  CHECK(ctx.validationMessageCount() == 0);
}
