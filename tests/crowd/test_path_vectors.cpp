#include <doctest/doctest.h>

#include <cmath>
#include <sstream>

#include "anim/default_clips.h"
#include "core/error.h"
#include "core/math.h"
#include "crowd/crowd_sim.h"
#include "crowd/path_vectors.h"
#include "test_support.h"

using namespace throng;

namespace {
// A walker annotated every `step` frames at 0.04 s per frame, moving by `velocity` m/s
// (data plane) from `from`, starting at `firstFrame`.
std::string walkerText(int ped, int firstFrame, int samples, int step, glm::vec2 from, glm::vec2 velocity) {
  std::ostringstream out;
  for (int k = 0; k < samples; ++k) {
    float t = float(k * step) * 0.04f;
    glm::vec2 p = from + velocity * t;
    out << firstFrame + k * step << '\t' << ped << ".0\t" << p.x << '\t' << p.y << '\n';
  }
  return out.str();
}
}  // namespace

TEST_CASE("path vectors: a straight walker gives equal one-second vectors, turned into world (x, -y)") {
  // 1.3 m/s along data +y, annotated every 0.4 s for 6 s.
  crowd::Trajectories t = crowd::parseTrajectories(walkerText(1, 0, 16, 10, {2.0f, 1.0f}, {0.0f, 1.3f}), "walker.txt");
  std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(t);
  REQUIRE(sources.size() == 1);
  const crowd::PathSource& s = sources[0];
  CHECK(s.startSecond == 0);
  CHECK(s.start.x == doctest::Approx(2.0f));
  CHECK(s.start.y == doctest::Approx(-1.0f));
  REQUIRE(s.vectors.size() == 6);  // samples at 0..6 s
  for (glm::vec2 v : s.vectors) {
    CHECK(v.x == doctest::Approx(0.0f));
    CHECK(v.y == doctest::Approx(-1.3f));
  }
  CHECK(s.meanSpeed() == doctest::Approx(1.3f));
}

TEST_CASE("path vectors: resampling interpolates between annotations on the file's clock") {
  // Person 1 starts the clock at frame 0. Person 2 is annotated from 0.4 s at a 0.667 s step
  // (biwi_eth's), so its first whole second of the shared clock is 1 s and positions there
  // are interpolated by hand: x(t) = 3 (t - 0.4) for t in [0.4, 1.734], then 4 + 1.5 (t - 1.734).
  crowd::TrajectoryOptions options;
  options.secondsPerStep = 0.667f;
  const std::string text =
      "0\t1\t0\t0\n10\t1\t0\t1\n"                 // person 1: 0 and 0.667 s
      "6\t2\t0\t0\n16\t2\t2.001\t0\n26\t2\t4.002\t0\n36\t2\t5.0025\t0\n";
  crowd::Trajectories t = crowd::parseTrajectories(text, "clock.txt", options);
  REQUIRE(t.frameStep == 10);
  std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(t);
  REQUIRE(sources.size() == 1);  // person 1 spans < 1 s: dropped
  const crowd::PathSource& s = sources[0];
  CHECK(s.id == 2);
  CHECK(s.startSecond == 1);
  const float spf = 0.0667f;
  auto x = [&](float time) {
    float t1 = 16 * spf, t2 = 26 * spf, t0 = 6 * spf;
    if (time <= t1) return 2.001f * (time - t0) / (t1 - t0);
    if (time <= t2) return 2.001f + 2.001f * (time - t1) / (t2 - t1);
    return 4.002f + 1.0005f * (time - t2) / (36 * spf - t2);
  };
  CHECK(s.start.x == doctest::Approx(x(1.0f)).epsilon(1e-4));
  REQUIRE(s.vectors.size() == 1);  // samples at 1 s and 2 s (the track ends at 2.4 s)
  CHECK(s.vectors[0].x == doctest::Approx(x(2.0f) - x(1.0f)).epsilon(1e-4));
  CHECK(s.vectors[0].y == doctest::Approx(0.0f));
}

TEST_CASE("path vectors: on a real file, vectors sum to the resampled displacement and speeds look human") {
  if (!test::haveSharedData("trajectories/sgan_format/crowds_zara01.txt")) return;
  crowd::Trajectories t = crowd::loadTrajectories(test::sharedDataDir() / "trajectories/sgan_format/crowds_zara01.txt");
  std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(t);
  CHECK(sources.size() == 148);  // every zara01 person spans more than 2 s
  std::vector<float> speeds = crowd::pathSpeeds(sources);
  std::sort(speeds.begin(), speeds.end());
  float median = speeds[speeds.size() / 2];
  MESSAGE("zara01: ", sources.size(), " sources, ", speeds.size(), " vectors, median speed ", median, " m/s");
  CHECK(median > 0.9f);
  CHECK(median < 1.4f);
  CHECK(speeds.back() < 4.0f);
}

TEST_CASE("path vectors: sources are assigned by speed range, deterministic per seed") {
  std::vector<crowd::PathSource> sources(4);
  const float speeds[] = {0.5f, 0.9f, 1.5f, 2.0f};
  for (int k = 0; k < 4; ++k) {
    sources[k].id = k;
    sources[k].vectors = {{speeds[k], 0.0f}, {0.0f, speeds[k]}};
  }
  std::vector<crowd::SpeedRange> ranges = {{0.4f, 1.2f}, {1.2f, 2.2f}, {3.0f, 4.0f}, {0.0f, 0.1f}, {1.0f, 1.1f}};
  std::vector<uint32_t> a = crowd::assignSources(sources, ranges, 3);
  CHECK((a[0] == 0 || a[0] == 1));
  CHECK((a[1] == 2 || a[1] == 3));
  CHECK(a[2] == 3);  // none in range: the nearest (fastest)
  CHECK(a[3] == 0);  // the slowest
  CHECK(a[4] == 1);  // 0.9 is 0.1 below, 1.5 is 0.4 above
  CHECK(crowd::assignSources(sources, ranges, 3) == a);
  std::vector<crowd::SpeedRange> many(200, crowd::SpeedRange{0.4f, 1.2f});
  std::vector<uint32_t> b = crowd::assignSources(sources, many, 9);
  CHECK(std::count(b.begin(), b.end(), 0u) > 60);  // both in-range sources get used
  CHECK(std::count(b.begin(), b.end(), 1u) > 60);
  CHECK_THROWS_AS(crowd::assignSources({}, ranges, 1), Error);
}

TEST_CASE("path vectors: speed weight from the clip pair's root speeds") {
  anim::ClipPair clips = anim::defaultRunPair();
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  float slow = anim::clipRootSpeed(pair.slow), fast = anim::clipRootSpeed(pair.fast);
  CHECK(slow == doctest::Approx(2.5f).epsilon(0.05));
  CHECK(fast == doctest::Approx(4.5f).epsilon(0.05));
  CHECK(crowd::speedWeight(slow, slow, fast) == 0.0f);
  CHECK(crowd::speedWeight(fast, slow, fast) == 1.0f);
  CHECK(crowd::speedWeight(0.5f * (slow + fast), slow, fast) == doctest::Approx(0.5f));
  CHECK(crowd::speedWeight(1.2f, slow, fast) == 0.0f);  // walkers clamp to the slow clip
  CHECK(crowd::speedWeight(9.0f, slow, fast) == 1.0f);
  CHECK(crowd::speedWeight(1.0f, 2.0f, 2.0f) == 0.0f);
}

TEST_CASE("path vectors: waypoints turn the source onto the agent's heading and loop") {
  std::vector<crowd::PathSource> sources(1);
  sources[0].vectors = {{1.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}};  // overall travel (2, 1)
  crowd::Crowd crowd;
  crowd.resize(2);
  crowd.placement[0] = glm::vec4(5.0f, 0.0f, 5.0f, 0.0f);          // faces +z
  crowd.placement[1] = glm::vec4(0.0f, 0.0f, 0.0f, 0.5f * kPi);    // faces +x
  std::vector<uint32_t> source = {0, 0};
  std::vector<float> maxSpeed = {2.0f, 2.0f};
  crowd::AgentPaths paths = crowd::followSources(crowd, sources, source, maxSpeed);
  CHECK(paths.waypoint(0, 0) == glm::vec2(5.0f, 5.0f));
  glm::vec2 end0 = paths.waypoint(0, 3) - paths.waypoint(0, 0);
  CHECK(end0.x == doctest::Approx(0.0f).epsilon(1e-5));
  CHECK(end0.y == doctest::Approx(std::sqrt(5.0f)));   // overall travel now faces +z
  glm::vec2 end1 = paths.waypoint(1, 3);
  CHECK(end1.x == doctest::Approx(std::sqrt(5.0f)));
  CHECK(std::abs(end1.y) < 1e-5f);
  // Looping: second 7 = two whole sequences + one vector.
  glm::vec2 loop = paths.waypoint(1, 7) - (2.0f * end1 + (paths.waypoint(1, 1)));
  CHECK(glm::length(loop) < 1e-5f);
  std::vector<glm::vec4> goals(2);
  crowd::writeGoals(paths, 0, goals);
  CHECK(goals[1] == glm::vec4(paths.waypoint(1, 1), 2.0f, 1.0f));
}

TEST_CASE("path vectors: an agent alone reproduces its source's displacement") {
  // Person 1: a curving walk annotated every 0.4 s for 8 s.
  std::ostringstream text;
  for (int k = 0; k <= 20; ++k) {
    float t = 0.4f * float(k);
    text << 10 * k << "\t1\t" << 1.2f * t << '\t' << 0.5f * std::sin(t) << '\n';
  }
  crowd::Trajectories t = crowd::parseTrajectories(text.str(), "curve.txt");
  std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(t);
  REQUIRE(sources.size() == 1);
  crowd::SimulationSetup setup = crowd::replaySetup(sources);
  for (crowd::SteerPolicy policy : {crowd::SteerPolicy::None, crowd::SteerPolicy::Rule, crowd::SteerPolicy::Ttc}) {
    CAPTURE(crowd::steerPolicyName(policy));
    crowd::SimulationOptions options;
    options.avoidance.policy = policy;
    options.seconds = 8.0f;
    crowd::SimulationResult r = crowd::simulateCrowd(nullptr, setup, options);
    // After 8 s it has left (its 8 vectors are done): its last recorded error is the end point's.
    CHECK(r.metrics.maxPathError < (policy == crowd::SteerPolicy::Ttc ? 0.3 : 1e-4));
    CHECK(r.metrics.collisions == 0);
    CHECK(r.metrics.speedSamples == 8);
    CHECK(r.metrics.meanSpeed == doctest::Approx(r.metrics.sourceMeanSpeed).epsilon(0.02));
  }
}
