// Menge scenarios as scenes (scene/menge_scene.h): the five shared scenes load; run on the GPU
// (steering with goals and walls, then synthesis, as a frame records them without the draw), no
// agent ever crosses a wall or comes within its radius of one (GPU readback, every step), and
// all but the trade show reach their end state: every agent at its final goal (the trade show's
// takes minutes: a test of its own, not in CI). The CPU twin (goal
// machines, navigation, steering and the wall constraint on the CPU) keeps the walls too.
#include <doctest/doctest.h>

#include <algorithm>

#include "anim/default_clips.h"
#include "crowd/avoidance.h"
#include "crowd/crowd_sim.h"
#include "crowd/goals.h"
#include "crowd/nav_jobs.h"
#include "crowd/obstacles.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "menge/menge.h"
#include "scene/frame_stages.h"
#include "scene/menge_scene.h"
#include "test_support.h"

using namespace throng;

namespace {

struct RunResult {
  double seconds = 0.0;
  bool done = false;
  uint32_t atGoal = 0;
  uint32_t atGoalAfterMinute = 0;  // at the first goal update after 60 s (or the end, if sooner)
  uint64_t stuckPlans = 0, crowdArrivals = 0;  // twin: the goal machine's (goals.h)
  crowd::WallViolations walls;
};

// Steps the scene (steer and synthesis stages) for at most `seconds`, updating the goals every
// half second and counting wall violations between consecutive steps on read-back positions.
RunResult runScene(scene::Scene& s, const crowd::WallGrid* walls, float radius, double seconds) {
  gpu::Context& ctx = test::gpuContext();
  const float dt = 1.0f / 30.0f;
  RunResult r;
  std::vector<glm::vec4> previous = gpu::readback<glm::vec4>(ctx, s.crowd().placement, s.count());
  const synth::CoverageCamera camera = synth::coverageCamera(glm::mat4(1.0f), 45.0f, 64, 64, 0.1f);
  for (int frame = 1; r.seconds < seconds; ++frame) {
    const scene::SceneStep step = s.advance(dt);
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      scene::SteerStage{&s, &step}.record(cmd);
      scene::SynthesisStage{&s, &step, camera, ctx.info().maxStorageBufferRange}.record(cmd);
    });
    r.seconds += dt;
    const std::vector<glm::vec4> now =
        gpu::readback<glm::vec4>(ctx, s.crowd().placement, s.count());
    if (walls) {
      const crowd::WallViolations v =
          crowd::countWallViolations(*walls, previous, now, radius - 0.001f);
      r.walls.crossings += v.crossings;
      r.walls.tooClose += v.tooClose;
      r.walls.closest = std::min(r.walls.closest, v.closest);
    }
    previous = now;
    if (frame % 15 == 0) {
      s.updateGoals(ctx);
      if (r.seconds < 60.01) r.atGoalAfterMinute = s.agentsAtGoal();
      if (s.goalsDone()) break;
    }
  }
  r.done = s.goalsDone();
  r.atGoal = s.agentsAtGoal();
  return r;
}

// The CPU twin of a goal scene for at most `seconds`: the goal machines every half second on
// the twin's positions, then per 0.05 s step navigation (navFollowCpu), grid, steering (with the
// walls), the kinematic advance and the wall constraint, counting wall violations between steps.
// Kinematic like crowd::simulateCrowd's twin, so its paths are not the render path's, but the
// walls' guarantee is the same.
RunResult runTwin(const scene::SceneSetup& setup, const crowd::WallGrid* walls, double seconds) {
  const size_t n = setup.crowd.size();
  const crowd::AvoidanceParams& params = setup.steering->avoidance;
  crowd::GoalMachine machine(*setup.steering->goals, n);
  const crowd::GoalScene& goals = machine.scene();
  std::vector<float> maxSpeed(n, 0.0f);
  for (size_t i = 0; i < n; ++i)
    if (goals.agentGroup[i] != crowd::kNoState)
      maxSpeed[i] = goals.groups[goals.agentGroup[i]].maxSpeed;
  std::vector<glm::vec4> placement = setup.crowd.placement, motion = setup.crowd.motion;
  std::vector<glm::vec4> steer(n, glm::vec4(0.0f)), targets(n, glm::vec4(0.0f)), previous;
  std::vector<glm::vec2> positions(n);
  std::vector<uint32_t> progress(n, 1u);
  auto evaluate = [&](double t) {
    for (size_t i = 0; i < n; ++i) positions[i] = {placement[i].x, placement[i].z};
    return machine.evaluate(positions, t, progress);
  };
  evaluate(0.0);
  crowd::NavPaths paths = crowd::packPaths(machine.paths(), maxSpeed);
  const float dt = 0.05f;
  RunResult r;
  for (uint32_t step = 0; r.seconds < seconds; ++step) {
    crowd::navFollowCpu(placement, paths, progress, goals.waypointReach, 1.0f, targets);
    crowd::SteerFrame frame;
    frame.dt = dt;
    frame.step = step;
    const crowd::Grid grid =
        crowd::buildGridCpu(placement, steer, params.cellSize, crowd::gridTable(uint32_t(n)));
    crowd::steerCpu(grid, params, frame, placement, motion, targets, steer, walls);
    previous = placement;
    crowd::advanceCpu(placement, steer, targets, dt);
    if (walls) {
      crowd::wallConstraintCpu(*walls, params.radius, previous, placement, 0, uint32_t(n));
      const crowd::WallViolations v =
          crowd::countWallViolations(*walls, previous, placement, params.radius - 0.001f);
      r.walls.crossings += v.crossings;
      r.walls.tooClose += v.tooClose;
    }
    r.seconds += dt;
    if ((step + 1) % 10 == 0) {
      const std::vector<uint32_t> changed = evaluate(r.seconds);
      if (!changed.empty()) {
        paths = crowd::packPaths(machine.paths(), maxSpeed);
        for (uint32_t i : changed) progress[i] = 1u;
      }
      if (r.seconds < 60.01) r.atGoalAfterMinute = machine.agentsAtGoal();
      if (machine.allDone()) break;
    }
  }
  r.done = machine.allDone();
  r.atGoal = machine.agentsAtGoal();
  r.stuckPlans = machine.stuckPlans();
  r.crowdArrivals = machine.crowdArrivals();
  return r;
}

}  // namespace

TEST_CASE("Menge scenes run with goals and walls: no wall crossed, all but the trade show finish") {
  if (!test::haveSharedData("scenes/menge")) return;
  struct Case {
    const char* name;
    double seconds;  // simulated
    bool mustFinish;
  };
  const Case cases[] = {{"4square", 90.0, true},
                        {"circle", 60.0, true},
                        {"bottleneck", 60.0, true},
                        {"stadium", 240.0, true},
                        {"tradeshow", 60.0, false}};
  for (const Case& c : cases) {
    const std::string name = c.name;
    CAPTURE(name);
    const menge::MengeScenario scenario = menge::readMengeProject(
        test::sharedDataDir() / "scenes/menge" / (std::string(c.name) + ".xml"));
    scene::MengeSceneResult m = scene::mengeScene(scenario, anim::defaultWalkPair(), 1, 0.05f);
    const size_t agents = m.setup.crowd.size();
    const crowd::AvoidanceParams avoidance = m.setup.steering->avoidance;
    const crowd::WallGrid walls = crowd::binWallsFor(m.setup.walls, avoidance);
    const bool hasWalls = !m.setup.walls.empty();
    const RunResult twin = runTwin(m.setup, hasWalls ? &walls : nullptr, c.seconds);
    scene::Scene s(test::gpuContext(), std::move(m.setup), {true, 0.05f, 20ull << 20}, {});
    const RunResult r = runScene(s, hasWalls ? &walls : nullptr, avoidance.radius, c.seconds);
    MESSAGE(std::string(c.name), ": ", agents, " agents, ", walls.segments.size(),
            " wall segments; after ", r.seconds, " s ", r.atGoal, " at their final goal",
            std::string(r.done ? " (all)" : ""), " (", r.atGoalAfterMinute, " after 60 s)",
            "; wall crossings ", r.walls.crossings, ", closer than the radius ", r.walls.tooClose,
            " | twin after ", twin.seconds, " s ", twin.atGoal, " at their final goal",
            std::string(twin.done ? " (all)" : ""), " (", twin.atGoalAfterMinute, " after 60 s; ",
            twin.stuckPlans, " stuck agents planned again, ", twin.crowdArrivals,
            " arrived in the crowd at their goal); wall crossings ", twin.walls.crossings,
            ", closer than the radius ", twin.walls.tooClose);
    CHECK(r.walls.crossings == 0);
    CHECK(r.walls.tooClose == 0);
    CHECK(twin.walls.crossings == 0);
    CHECK(twin.walls.tooClose == 0);
    if (c.mustFinish) CHECK(r.done);
  }
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

// The two large scenes to their end state (everyone at a final goal or waiting there), GPU path:
// about 4 minutes on 2 cores (the trade show ends after about 6 simulated minutes), so not in
// CI; run it with --no-skip.
TEST_CASE("Menge stadium and tradeshow reach their end state (long)" * doctest::skip()) {
  if (!test::haveSharedData("scenes/menge")) return;
  for (const char* name : {"stadium", "tradeshow"}) {
    CAPTURE(name);
    const menge::MengeScenario scenario = menge::readMengeProject(
        test::sharedDataDir() / "scenes/menge" / (std::string(name) + ".xml"));
    scene::MengeSceneResult m = scene::mengeScene(scenario, anim::defaultWalkPair(), 1, 0.05f);
    const crowd::AvoidanceParams avoidance = m.setup.steering->avoidance;
    const crowd::WallGrid walls = crowd::binWallsFor(m.setup.walls, avoidance);
    scene::Scene s(test::gpuContext(), std::move(m.setup), {true, 0.05f, 20ull << 20}, {});
    const RunResult r = runScene(s, &walls, avoidance.radius, 900.0);
    MESSAGE(std::string(name), ": after ", r.seconds, " s ", r.atGoal, " of ", s.count(),
            " at their final goal", std::string(r.done ? " (all)" : ""), "; wall crossings ",
            r.walls.crossings, ", closer than the radius ", r.walls.tooClose);
    CHECK(r.done);
    CHECK(r.walls.crossings == 0);
    CHECK(r.walls.tooClose == 0);
  }
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

TEST_CASE("Menge bottleneck scaled to 200 agents: flow through the 2 m opening") {
  if (!test::haveSharedData("scenes/menge/bottleneck.xml")) return;
  // Menge's profile radius (0.19 m), then Throng's default safe radius (0.3 m).
  for (const float radius : {0.0f, 0.3f}) {
    CAPTURE(radius);
    menge::MengeScenario scenario =
        menge::readMengeProject(test::sharedDataDir() / "scenes/menge/bottleneck.xml");
    // The scene's geometry and behaviour with 200 agents instead of its 5: a 20 × 10 grid 0.8 m
    // apart below the opening (the 2 m wide, 10 m long gap between the blocks at |x| > 1).
    const uint32_t group = scenario.scene.agents.front().group;
    scenario.scene.agents.clear();
    for (int row = 0; row < 10; ++row)
      for (int col = 0; col < 20; ++col)
        scenario.scene.agents.push_back({glm::vec2(-7.6f + 0.8f * col, -7.0f - 0.8f * row), group});
    scene::MengeSceneResult m = scene::mengeScene(scenario, anim::defaultWalkPair(), 1, 0.05f);
    if (radius > 0.0f) m.setup.steering->avoidance.radius = radius;
    const crowd::AvoidanceParams avoidance = m.setup.steering->avoidance;
    const crowd::WallGrid walls = crowd::binWallsFor(m.setup.walls, avoidance);
    scene::Scene s(test::gpuContext(), std::move(m.setup), {true, 0.05f, 20ull << 20}, {});
    gpu::Context& ctx = test::gpuContext();
    const float dt = 1.0f / 30.0f;
    const synth::CoverageCamera camera =
        synth::coverageCamera(glm::mat4(1.0f), 45.0f, 64, 64, 0.1f);
    std::vector<glm::vec4> previous = gpu::readback<glm::vec4>(ctx, s.crowd().placement, s.count());
    std::vector<double> crossed;  // when each agent passed the middle of the opening (z = 0)
    std::vector<bool> passed(s.count(), false);
    crowd::WallViolations violations;
    double t = 0.0;
    for (int frame = 1; t < 150.0 && crossed.size() < s.count(); ++frame) {
      const scene::SceneStep step = s.advance(dt);
      gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
        scene::SteerStage{&s, &step}.record(cmd);
        scene::SynthesisStage{&s, &step, camera, ctx.info().maxStorageBufferRange}.record(cmd);
      });
      t += dt;
      const std::vector<glm::vec4> now =
          gpu::readback<glm::vec4>(ctx, s.crowd().placement, s.count());
      const crowd::WallViolations v =
          crowd::countWallViolations(walls, previous, now, avoidance.radius - 0.001f);
      violations.crossings += v.crossings;
      violations.tooClose += v.tooClose;
      for (uint32_t i = 0; i < s.count(); ++i)
        if (!passed[i] && previous[i].z < 0.0f && now[i].z >= 0.0f) {
          passed[i] = true;
          crossed.push_back(t);
        }
      previous = now;
      if (frame % 15 == 0) s.updateGoals(ctx);
    }
    REQUIRE(crossed.size() >= 100);
    // The steady part: from the 10th to the 90th percentile of the passages.
    std::sort(crossed.begin(), crossed.end());
    const size_t lo = crossed.size() / 10, hi = crossed.size() * 9 / 10;
    const double flow = double(hi - lo) / (crossed[hi] - crossed[lo]) / 2.0;  // per metre width
    MESSAGE("bottleneck, 200 agents, radius ", avoidance.radius, " m: ", crossed.size(),
            " passed the 2 m opening in ", t, " s; specific flow ", flow,
            " persons/m/s (from passages ", lo, " to ", hi, "); wall crossings ",
            violations.crossings, ", too close ", violations.tooClose);
    for (uint32_t i = 0; i < s.count(); ++i)
      if (!passed[i])
        MESSAGE("not through: agent ", i, " at (", previous[i].x, ", ", previous[i].z, ")");
    // Everyone gets through: agents that reach the goal stay there (they do not walk back to
    // the road map's nearest way point in the opening and block it).
    CHECK(crossed.size() == s.count());
    CHECK(violations.crossings == 0);
    CHECK(violations.tooClose == 0);
    CHECK(flow > 0.3);  // agents do stream through
    // With the density-dependent speed (Weidmann) the flow falls near the 1.5–2 persons/m/s
    // measured in bottlenecks of this width (docs/performance.md); without it it is 4–6.
    CHECK(flow < 3.0);
    CHECK(ctx.validationMessageCount() == 0);
  }
}
