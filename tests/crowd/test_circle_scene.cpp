// The circle scene steered along lane waypoints with avoidance (crowd/circle_paths.h) against
// re-aiming at the tangent, on the CPU twins of the render path's passes.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "anim/default_clips.h"
#include "core/error.h"
#include "crowd/circle_paths.h"
#include "crowd/scenario.h"

using namespace throng;

namespace {
// THRONG_CIRCLE_RUNNERS / THRONG_CIRCLE_SECONDS scale the run up (the figures: 3000
// runners, 60 s); the default keeps the suite quick.
float fromEnvironment(const char* name, float fallback) {
  const char* text = std::getenv(name);
  return text && *text ? std::stof(text) : fallback;
}
}  // namespace

TEST_CASE("circle scene: lane waypoints keep the radius and avoidance keeps runners apart") {
  crowd::ScenarioOptions scenario;
  scenario.name = "circle";
  scenario.characters = uint32_t(fromEnvironment("THRONG_CIRCLE_RUNNERS", 600.0f));
  const float seconds = fromEnvironment("THRONG_CIRCLE_SECONDS", 20.0f);
  const crowd::Crowd crowd = crowd::makeScenario(scenario);
  const anim::ClipPair clips = anim::defaultRunPair();
  const anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  const crowd::AgentPaths paths =
      crowd::circlePaths(crowd, anim::clipRootSpeed(pair.slow), anim::clipRootSpeed(pair.fast));
  CHECK(paths.cumulative.size() < crowd.size());  // runners of one lane and speed share a lap
  const float dt = 1.0f / 30.0f;
  crowd::AvoidanceParams params;
  const crowd::CircleRunFigures tangent =
      crowd::runCircleCpu(pair, crowd, nullptr, params, dt, seconds);
  params.policy = crowd::SteerPolicy::None;
  const crowd::CircleRunFigures lanes =
      crowd::runCircleCpu(pair, crowd, &paths, params, dt, seconds);
  params.policy = crowd::SteerPolicy::Ttc;
  const crowd::CircleRunFigures avoiding =
      crowd::runCircleCpu(pair, crowd, &paths, params, dt, seconds);
  auto describe = [](const char* what, const crowd::CircleRunFigures& f) {
    MESSAGE(std::string(what), ": mean radius drift ", f.meanRadiusDrift, " m (mean |drift| ",
            f.meanAbsRadiusError, " m), pairs closer than 0.6 m: ", f.minClosePairs, "..",
            f.maxClosePairs, " (mean ", f.meanClosePairs, ")");
  };
  MESSAGE(scenario.characters, " runners, ", seconds, " s");
  describe("tangent re-aiming", tangent);
  describe("lane waypoints, no avoidance", lanes);
  describe("lane waypoints, TTC avoidance", avoiding);
  CHECK(tangent.meanRadiusDrift > 0.1);  // the spiral the waypoints cure
  CHECK(std::abs(lanes.meanRadiusDrift) < 0.05);
  CHECK(std::abs(avoiding.meanRadiusDrift) < 0.1);
  CHECK(avoiding.meanAbsRadiusError < 0.3);
  CHECK(avoiding.meanClosePairs < 0.25 * tangent.meanClosePairs);
  CHECK(avoiding.maxClosePairs < tangent.maxClosePairs);
}

TEST_CASE("circle scene: laps close exactly and bad input is an error") {
  crowd::Crowd crowd;
  crowd.resize(2);
  crowd.placement[0] = glm::vec4(10.0f, 0.0f, 0.0f, 0.0f);
  crowd.placement[1] = glm::vec4(0.0f, 0.0f, -12.0f, 0.0f);
  crowd.motion[0] = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
  crowd.motion[1] = glm::vec4(0.0f, 1.0f, 1.0f, 1.0f);
  const crowd::AgentPaths paths = crowd::circlePaths(crowd, 3.0f, 4.0f);
  REQUIRE(paths.size() == 2);
  const uint32_t lap = uint32_t(paths.cumulative[paths.source[0]].size() - 1);
  CHECK(lap == 21);  // 2π·10 m at 3 m/s
  for (uint32_t j : {0u, 5u, lap, 3 * lap + 7}) {
    const glm::vec2 w = paths.waypoint(0, j);
    CHECK(glm::length(w) == doctest::Approx(10.0f).epsilon(1e-4));
  }
  CHECK(glm::length(paths.waypoint(0, lap) - paths.waypoint(0, 0)) < 1e-4f);
  // Counter-clockwise, as anim::circleHeading: from (10, 0) towards +z.
  CHECK(paths.waypoint(0, 1).y > 0.0f);
  CHECK(glm::length(paths.waypoint(1, 0) - glm::vec2(0.0f, -12.0f)) < 1e-4f);
  CHECK(glm::length(paths.waypoint(1, 1)) == doctest::Approx(12.0f).epsilon(1e-4));
  crowd.placement[1] = glm::vec4(0.0f);
  CHECK_THROWS_AS(crowd::circlePaths(crowd, 3.0f, 4.0f), Error);
  CHECK_THROWS_AS(crowd::circlePaths(crowd, 0.0f, 4.0f), Error);
  const std::vector<glm::vec4> close = {
      {0, 0, 0, 0}, {0.5f, 0, 0, 0}, {0, 0, 0.59f, 0}, {5, 0, 5, 0}};
  CHECK(crowd::countClosePairs(close, 0.6f) == 2);
}
