#include <doctest/doctest.h>

#include <limits>

#include "core/error.h"
#include "crowd/path_goals.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"

using namespace throng;

namespace {
crowd::PathSource source(glm::vec2 start, std::vector<glm::vec2> vectors,
                         uint32_t startSecond = 0) {
  crowd::PathSource s;
  s.start = start;
  s.startSecond = startSecond;
  s.vectors = std::move(vectors);
  return s;
}
}  // namespace

TEST_CASE(
    "path goals: the GPU pass writes writeGoals' waypoints, second by second, looping and inactive "
    "alike") {
  // Storyboard agents (looping their source, turned onto their heading) and a replay (each
  // source at its own place and time, leaving when its vectors end) in one set of paths.
  std::vector<crowd::PathSource> sources = {
      source({0, 0}, {{0.0f, 1.2f}, {0.3f, 1.1f}, {0.5f, 0.9f}}),
      source({5, -2}, {{-1.0f, 0.2f}, {-1.1f, 0.0f}, {-0.9f, -0.4f}, {-1.0f, 0.0f}, {-1.2f, 0.1f}},
             3)};
  crowd::Crowd crowd;
  crowd.resize(5);
  for (size_t i = 0; i < 5; ++i)
    crowd.placement[i] = glm::vec4(float(i), 0.0f, -float(i), 0.7f * float(i));
  crowd::AgentPaths paths =
      crowd::followSources(crowd, sources, std::vector<uint32_t>{0, 1, 0, 1, 1},
                           std::vector<float>{1.5f, 2.0f, 1.0f, 1.8f, 2.2f});
  paths.lastSecond[4] = 0;  // never active (a talker)
  crowd::AgentPaths replay = crowd::replaySources(sources, {1.0f, 1.0f}, 2.5f);
  // Both path sets share one upload when concatenated: check each separately instead.
  for (const crowd::AgentPaths* p : {&paths, &replay}) {
    gpu::Context& ctx = test::gpuContext();
    crowd::AvoidancePrograms programs(ctx);
    crowd::PathBuffers buffers = crowd::uploadPaths(ctx, *p);
    std::vector<glm::vec4> zero(p->size(), glm::vec4(-7.0f));
    crowd::SteerBuffers agents = crowd::uploadSteer(ctx, zero, zero);
    float worst = 0.0f;
    for (uint32_t second = 0; second < 20; ++second) {
      crowd::GoalJob job{&buffers, &agents, second};
      REQUIRE(job.validate().empty());
      gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) { job.record(cmd, programs); });
      std::vector<glm::vec4> gpuGoals = gpu::readback<glm::vec4>(ctx, agents.goals, p->size());
      std::vector<glm::vec4> cpuGoals(p->size());
      crowd::writeGoals(*p, second, cpuGoals);
      for (size_t i = 0; i < p->size(); ++i) {
        CAPTURE(second);
        CAPTURE(i);
        CHECK(gpuGoals[i].w == cpuGoals[i].w);
        CHECK(gpuGoals[i].z == cpuGoals[i].z);
        worst = std::max(worst, glm::length(glm::vec2(gpuGoals[i]) - glm::vec2(cpuGoals[i])));
      }
    }
    CHECK(worst < 1e-5f);
    CHECK(ctx.validationMessageCount() == 0);
  }
}

TEST_CASE("path goals: mismatched buffers are reported") {
  gpu::Context& ctx = test::gpuContext();
  crowd::AvoidancePrograms programs(ctx);
  crowd::GoalJob job;
  CHECK(job.validate().size() == 2);
  CHECK_THROWS_WITH_AS(job.record(VK_NULL_HANDLE, programs),
                       doctest::Contains("GoalJob is invalid"), Error);
  std::vector<crowd::PathSource> sources = {source({0, 0}, {{1.0f, 0.0f}})};
  crowd::Crowd crowd;
  crowd.resize(3);
  crowd::AgentPaths paths = crowd::followSources(crowd, sources, std::vector<uint32_t>(3, 0),
                                                 std::vector<float>(3, 1.0f));
  crowd::PathBuffers buffers = crowd::uploadPaths(ctx, paths);
  std::vector<glm::vec4> two(2);
  crowd::SteerBuffers agents = crowd::uploadSteer(ctx, two, two);
  job = {&buffers, &agents, 0};
  CHECK(job.validate().front().find("3 agents but the steering buffers 2") != std::string::npos);
  paths.source[1] = 5;
  CHECK_THROWS_WITH_AS(crowd::uploadPaths(ctx, paths), doctest::Contains("follows source 5 of 1"),
                       Error);
}
