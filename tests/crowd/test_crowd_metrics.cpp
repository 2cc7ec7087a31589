#include <doctest/doctest.h>

#include "core/rng.h"
#include "crowd/crowd_metrics.h"
#include "crowd/crowd_sim.h"
#include "test_support.h"

using namespace throng;

TEST_CASE("metrics: KS distance of known samples") {
  std::vector<float> a = {1, 2, 3, 4};
  CHECK(crowd::ksDistance(a, a) == 0.0);
  std::vector<float> shuffled = {4, 1, 3, 2,
                                 2, 1, 4, 3};  // the same distribution, twice the samples
  CHECK(crowd::ksDistance(a, shuffled) == 0.0);
  CHECK(crowd::ksDistance(a, std::vector<float>{3, 4, 5, 6}) == doctest::Approx(0.5));
  CHECK(crowd::ksDistance(a, std::vector<float>{10, 11}) == 1.0);
  CHECK(crowd::ksDistance(a, std::vector<float>{}) == 0.0);
  // Two large samples of one uniform distribution: close to 0; of shifted ones: about the shift.
  Rng rng(3);
  std::vector<float> u1, u2, shifted;
  for (int k = 0; k < 20000; ++k) {
    u1.push_back(rng.uniform());
    u2.push_back(rng.uniform());
    shifted.push_back(rng.uniform() + 0.25f);
  }
  CHECK(crowd::ksDistance(u1, u2) < 0.02);
  CHECK(crowd::ksDistance(u1, shifted) == doctest::Approx(0.25).epsilon(0.1));
}

TEST_CASE("metrics: collisions count overlap onsets per agent, over agent-seconds") {
  crowd::CollisionCounter counter(0.3f);
  std::vector<uint8_t> active = {1, 1, 1};
  // Agents 0 and 1 approach (1.0 m, 0.5 m: overlapping, 0.4 m, then apart, then together again);
  // agent 2 stays away.
  const float gaps[] = {1.0f, 0.5f, 0.4f, 0.9f, 0.2f};
  for (float gap : gaps) {
    std::vector<glm::vec4> p = {{0, 0, 0, 0}, {gap, 0, 0, 0}, {50, 0, 50, 0}};
    counter.addStep(p, active, 0.1f);
  }
  CHECK(counter.collisions() == 4);  // two onsets, each for both agents
  CHECK(counter.agentSeconds() == doctest::Approx(1.5));
  CHECK(counter.perAgentSecond() == doctest::Approx(4.0 / 1.5));
  CHECK(counter.overlapShare() == doctest::Approx(6.0 / 15.0));
  // An inactive agent never collides.
  crowd::CollisionCounter other(0.3f);
  std::vector<glm::vec4> p = {{0, 0, 0, 0}, {0.1f, 0, 0, 0}};
  std::vector<uint8_t> one = {1, 0};
  other.addStep(p, one, 0.5f);
  CHECK(other.collisions() == 0);
  CHECK(other.agentSeconds() == doctest::Approx(0.5));
}

TEST_CASE(
    "metrics: a replay without avoidance reproduces the real people (path error 0, same speeds)") {
  if (!test::haveSharedData("trajectories/sgan_format/crowds_zara01.txt")) return;
  crowd::Trajectories t =
      crowd::loadTrajectories(test::sharedDataDir() / "trajectories/sgan_format/crowds_zara01.txt");
  std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(t);
  crowd::SimulationSetup setup = crowd::replaySetup(sources);
  crowd::SimulationOptions options;
  options.avoidance.policy = crowd::SteerPolicy::None;
  options.seconds = 120.0f;
  options.dt = 0.1f;
  crowd::SimulationResult r = crowd::simulateCrowd(nullptr, setup, options);
  const crowd::CrowdMetrics real = crowd::trajectoryMetrics(t, 0.3f);
  MESSAGE("zara01 real: ", real.collisionsPerAgentSecond,
          " collisions/agent-s; replay (none): ", r.metrics.collisionsPerAgentSecond, ", KS ",
          r.metrics.speedKs, ", path error ", r.metrics.maxPathError);
  CHECK(r.metrics.maxPathError < 1e-3);
  CHECK(r.metrics.speedKs < 0.02);  // float rounding only
  CHECK(r.metrics.meanSpeed == doctest::Approx(r.metrics.sourceMeanSpeed).epsilon(1e-3));
  CHECK(r.metrics.agents == sources.size());
  CHECK(real.agentSeconds > 1000.0);
  CHECK(real.speedSamples > 1000);
  CHECK(real.peakDensity > 0.0);
}

TEST_CASE("metrics: collisions at the body radius, safe-radius intrusions apart") {
  // Two people side by side 0.7 m apart, then 0.5 m apart: neither touches a 0.2 m body
  // (0.4 m), both come inside the 0.3 m safe radius (0.6 m) once.
  std::string text;
  for (int k = 0; k <= 20; ++k) {
    const float gap = k < 10 ? 0.7f : 0.5f;
    text += std::to_string(10 * k) + " 1 " + std::to_string(0.5f * float(k)) + " 0\n";
    text += std::to_string(10 * k) + " 2 " + std::to_string(0.5f * float(k)) + " " +
            std::to_string(gap) + "\n";
  }
  const crowd::Trajectories t = crowd::parseTrajectories(text, "side.txt");
  const crowd::CrowdMetrics m = crowd::trajectoryMetrics(t, 0.3f);
  CHECK(m.bodyRadius == doctest::Approx(crowd::kBodyRadius));
  CHECK(m.safeRadius == doctest::Approx(0.3f));
  CHECK(m.collisions == 0);
  CHECK(m.collisionsPerAgentSecond == 0.0);
  CHECK(m.safeIntrusions == 2);
  CHECK(m.safeIntrusionsPerAgentSecond == doctest::Approx(2.0 / m.agentSeconds));
  const crowd::CrowdMetrics wide = crowd::trajectoryMetrics(t, 0.3f, 0.26f);
  CHECK(wide.collisions == 2);  // 0.5 m < 2 × 0.26 m
  const std::string json = crowd::metricsJson(m);
  CHECK(json.find("\"safe_intrusions\":2") != std::string::npos);
  CHECK(crowd::formatMetrics("real", m).find("safe-radius (0.3 m) intrusions") !=
        std::string::npos);
}

TEST_CASE("metrics: the text report gives each figure a fixed precision with its unit") {
  crowd::CrowdMetrics m;
  m.agents = 12;
  m.seconds = 20.0;
  m.agentSeconds = 243.0;
  m.collisions = 2;
  m.collisionsPerAgentSecond = 2.0 / 243.0;  // 0.00823045…
  m.overlapShare = 0.00329218;
  m.safeRadius = 0.3f;
  m.safeIntrusionsPerAgentSecond = 0.0123457;
  m.meanSpeed = 1.033333;
  m.sourceMeanSpeed = 1.2;
  m.speedKs = 0.123456;
  m.meanPathError = 0.104;
  m.p95PathError = 0.2;
  m.maxPathError = 1.0 / 3.0;
  m.peakDensity = 1.25;
  const std::string text = crowd::formatMetrics("policy x", m);
  INFO(text);
  for (const char* part :
       {"policy x: 12 agents, 20 s, 243 agent-s\n",
        "collisions per agent-second 0.0082 at body radius 0.2 m (2 agent events)",
        "overlapping 0.33 % of agent-steps",
        "safe-radius (0.3 m) intrusions per agent-second 0.0123",
        "speed: mean 1.03 m/s (sources 1.20 m/s), KS distance 0.123 over",
        "path error: mean 0.10 m, p95 0.20 m, max 0.33 m", "peak density 1.25 agents/m^2"})
    CHECK(text.find(part) != std::string::npos);
}
