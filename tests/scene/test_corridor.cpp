// The storyboard paper's corridor (scene/corridor_scene.h): walkers follow path vectors of real
// tracked people (UCY zara01, ../shared/data) along the corridor and the walls to the far end.
// Over 60 s nobody crosses a wall or leaves the walkable area (the rectangle between the walls),
// counted on the CPU twin (crowd::simulateCrowd without a device, kinematic) and on a GPU
// readback of the render path (steering, root motion, wall constraint) after every frame; how
// many walkers reach the far end is reported. Also: the held path ends on the GPU pass match the
// twin, and without the tracked set the scene falls back to goals.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include "crowd/crowd_sim.h"
#include "crowd/obstacles.h"
#include "crowd/path_goals.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "scene/corridor_scene.h"
#include "scene/frame_stages.h"
#include "test_support.h"

using namespace throng;

namespace {

constexpr const char* kTracked = "trajectories/sgan_format/crowds_zara01.txt";

// The x range the corridor's walls span (they reach past both open ends).
glm::vec2 wallSpan(const crowd::Obstacles& walls) {
  glm::vec2 span(1e30f, -1e30f);
  for (const crowd::Segment& s : walls.segments)
    span = {std::min({span.x, s.a.x, s.b.x}), std::max({span.y, s.a.x, s.b.x})};
  return span;
}

// Counts over a run: wall crossings and approaches between consecutive positions, agents outside
// the rectangle between the walls (|z| ≥ width / 2 or past the walls' ends) at any step.
struct Tally {
  const crowd::WallGrid* walls = nullptr;
  float radius = 0.0f, wallsFrom = 0.0f, wallsTo = 0.0f, halfWidth = 0.0f;
  crowd::WallViolations violations;
  size_t outside = 0;
  std::vector<glm::vec4> previous;

  void add(std::span<const glm::vec4> now) {
    if (!previous.empty()) {
      const crowd::WallViolations v =
          crowd::countWallViolations(*walls, previous, now, radius - 0.001f);
      violations.crossings += v.crossings;
      violations.tooClose += v.tooClose;
    }
    for (const glm::vec4& p : now)
      outside += std::abs(p.z) >= halfWidth || p.x < wallsFrom || p.x > wallsTo ? 1 : 0;
    previous.assign(now.begin(), now.end());
  }
};

// Walkers past the end they walk to (x beyond length / 2 in their direction).
size_t atFarEnd(std::span<const glm::vec4> placement, std::span<const int> dirs, float halfLength) {
  size_t n = 0;
  for (size_t i = 0; i < dirs.size(); ++i)
    n += dirs[i] != 0 && float(dirs[i]) * placement[i].x >= halfLength ? 1 : 0;
  return n;
}

class TallyObserver : public crowd::StepObserver {
 public:
  explicit TallyObserver(Tally& tally) : tally_(tally) {}
  void observe(uint64_t, std::span<const glm::vec4> placement, std::span<const uint8_t>) override {
    tally_.add(placement);
  }

 private:
  Tally& tally_;
};

struct CorridorRun {
  size_t agents = 0, walkers = 0, twinAtEnd = 0, gpuAtEnd = 0;
  Tally twin, gpu;
};

// Builds the corridor of `length` on the tracked set, runs the twin and the render path 60 s.
CorridorRun runCorridor(float length, double seconds) {
  scene::CorridorDescription d;
  d.length = length;
  d.trajectories = (test::sharedDataDir() / kTracked).string();
  scene::SceneSetup setup = scene::corridorScene(d);
  REQUIRE(setup.steering);
  REQUIRE(!setup.steering->goals);
  const std::vector<int> dirs = scene::corridorDirections(setup);
  CorridorRun run;
  run.agents = setup.crowd.size();
  run.walkers = size_t(std::count_if(dirs.begin(), dirs.end(), [](int v) { return v != 0; }));
  const crowd::AvoidanceParams avoidance = setup.steering->avoidance;
  const crowd::WallGrid walls = crowd::binWallsFor(setup.walls, avoidance);
  const glm::vec2 span = wallSpan(setup.walls);
  const Tally blank{&walls, avoidance.radius, span.x, span.y, 0.5f * d.width, {}, 0, {}};
  run.twin = run.gpu = blank;

  crowd::SimulationOptions options;
  options.avoidance = avoidance;
  options.dt = 0.05f;
  options.seconds = float(seconds);
  options.walls = &setup.walls;
  TallyObserver observer(run.twin);
  options.observer = &observer;
  const crowd::SimulationResult twin =
      crowd::simulateCrowd(nullptr, {setup.crowd, setup.steering->paths}, options);
  run.twinAtEnd = atFarEnd(twin.crowd.placement, dirs, 0.5f * d.length);

  gpu::Context& ctx = test::gpuContext();
  scene::Scene s(ctx, std::move(setup), {true, 0.05f, 20ull << 20}, {});
  const synth::CoverageCamera camera = synth::coverageCamera(glm::mat4(1.0f), 45.0f, 64, 64, 0.1f);
  const float dt = 1.0f / 30.0f;
  run.gpu.add(gpu::readback<glm::vec4>(ctx, s.crowd().placement, s.count()));
  for (int frame = 1; frame <= int(std::lround(seconds / dt)); ++frame) {
    const scene::SceneStep step = s.advance(dt);
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      scene::SteerStage{&s, &step}.record(cmd);
      scene::SynthesisStage{&s, &step, camera, ctx.info().maxStorageBufferRange}.record(cmd);
    });
    run.gpu.add(gpu::readback<glm::vec4>(ctx, s.crowd().placement, s.count()));
  }
  run.gpuAtEnd = atFarEnd(run.gpu.previous, dirs, 0.5f * d.length);
  MESSAGE("corridor ", length, " x ", d.width, " m (walls from x = ", span.x, " to ", span.y,
          " m): ", run.agents, " agents (", run.walkers, " walkers); after ", seconds,
          " s at the far end: twin ", run.twinAtEnd, ", GPU ", run.gpuAtEnd,
          "; wall crossings twin ", run.twin.violations.crossings, ", GPU ",
          run.gpu.violations.crossings, "; closer than the radius twin ",
          run.twin.violations.tooClose, ", GPU ", run.gpu.violations.tooClose,
          "; agent-steps outside twin ", run.twin.outside, ", GPU ", run.gpu.outside);
  CHECK(ctx.validationMessageCount() == 0);
  return run;
}

void checkNobodyLeaves(const CorridorRun& r) {
  CHECK(r.twin.violations.crossings == 0);
  CHECK(r.twin.violations.tooClose == 0);
  CHECK(r.twin.outside == 0);
  CHECK(r.gpu.violations.crossings == 0);
  CHECK(r.gpu.violations.tooClose == 0);
  CHECK(r.gpu.outside == 0);
}

}  // namespace

TEST_CASE("the corridor: walkers' paths are tracked people's vectors along it, inside the walls") {
  if (!test::haveSharedData(kTracked)) return;
  scene::CorridorDescription d;
  d.trajectories = (test::sharedDataDir() / kTracked).string();
  const scene::SceneSetup setup = scene::corridorScene(d);
  REQUIRE(setup.steering);
  REQUIRE(!setup.steering->goals);
  const crowd::AgentPaths& paths = setup.steering->paths;
  REQUIRE(paths.size() == setup.crowd.size());
  const std::vector<int> dirs = scene::corridorDirections(setup);
  const glm::vec2 span = wallSpan(setup.walls);
  size_t forward = 0, backward = 0, turned = 0, seconds = 0;
  for (size_t i = 0; i < paths.size(); ++i) {
    CAPTURE(i);
    const std::vector<glm::vec2>& c = paths.cumulative[paths.source[i]];
    CHECK(paths.holds(paths.source[i]));
    if (dirs[i] == 0) {
      CHECK(paths.waypoint(i, 100) == paths.start[i]);  // talkers stand
      continue;
    }
    (dirs[i] > 0 ? forward : backward) += 1;
    seconds += c.size() - 1;
    for (uint32_t j = 1; j < c.size(); ++j) {
      const glm::vec2 w = paths.waypoint(i, j);
      CHECK(std::abs(w.y) <= 0.5f * d.width - 0.75f + 1e-4f);
      // Real people's vectors: some step sideways or briefly back, none jumps.
      const glm::vec2 step = c[j] - c[j - 1];
      CHECK(glm::length(step) <= 1.25f * paths.maxSpeed[i]);
      turned += float(dirs[i]) * step.x < 0.5f * glm::length(step) ? 1 : 0;
    }
    // The last waypoint lies past the far end, 2 m or more inside the walls, and is held there.
    const float endX = paths.waypoint(i, uint32_t(c.size() - 1)).x;
    CHECK(float(dirs[i]) * endX >= 0.5f * d.length + 0.5f - 1e-3f);
    CHECK(endX >= span.x + 2.0f - 1e-3f);
    CHECK(endX <= span.y - 2.0f + 1e-3f);
    CHECK(paths.waypoint(i, uint32_t(c.size() + 50)) == paths.waypoint(i, uint32_t(c.size() - 1)));
  }
  MESSAGE("corridor paths: ", forward, " walkers to +x, ", backward, " to -x, ",
          paths.size() - forward - backward, " standing; ", turned, " of ", seconds,
          " path seconds more than 60 degrees off the corridor's axis");
  CHECK(forward > 100);  // both directions, as in the storyboard
  CHECK(backward > 100);
}

TEST_CASE("the corridor: held path ends on the GPU pass match writeGoals") {
  if (!test::haveSharedData(kTracked)) return;
  scene::CorridorDescription d;
  d.trajectories = (test::sharedDataDir() / kTracked).string();
  const scene::SceneSetup setup = scene::corridorScene(d);
  const crowd::AgentPaths& p = setup.steering->paths;
  gpu::Context& ctx = test::gpuContext();
  crowd::AvoidancePrograms programs(ctx);
  const crowd::PathBuffers buffers = crowd::uploadPaths(ctx, p);
  std::vector<glm::vec4> zero(p.size(), glm::vec4(-7.0f));
  crowd::SteerBuffers agents = crowd::uploadSteer(ctx, zero, zero);
  float worst = 0.0f;
  for (uint32_t second : {0u, 1u, 20u, 45u, 200u, 5000u}) {
    CAPTURE(second);
    crowd::GoalJob job{&buffers, &agents, second};
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) { job.record(cmd, programs); });
    const std::vector<glm::vec4> gpuGoals = gpu::readback<glm::vec4>(ctx, agents.goals, p.size());
    std::vector<glm::vec4> cpuGoals(p.size());
    crowd::writeGoals(p, second, cpuGoals);
    for (size_t i = 0; i < p.size(); ++i) {
      CHECK(gpuGoals[i].w == cpuGoals[i].w);
      CHECK(gpuGoals[i].z == cpuGoals[i].z);
      worst = std::max(worst, glm::length(glm::vec2(gpuGoals[i]) - glm::vec2(cpuGoals[i])));
    }
  }
  CHECK(worst < 1e-4f);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("the corridor without its tracked set: walkers head for the far end by goals") {
  scene::CorridorDescription d;
  d.trajectories = "no/such/tracks.txt";
  const scene::SceneSetup setup = scene::corridorScene(d);
  REQUIRE(setup.steering);
  CHECK(setup.steering->goals);
  CHECK(setup.steering->paths.size() == 0);
  const std::vector<int> dirs = scene::corridorDirections(setup);
  CHECK(std::count(dirs.begin(), dirs.end(), 1) > 100);
  CHECK(std::count(dirs.begin(), dirs.end(), -1) > 100);
}

TEST_CASE("the corridor, about 500 people on tracked path vectors: nobody leaves it in 60 s") {
  if (!test::haveSharedData(kTracked)) return;
  const CorridorRun r = runCorridor(60.0f, 60.0);
  CHECK(r.agents > 400);
  CHECK(r.agents < 650);
  checkNobodyLeaves(r);
  // A 60 m corridor at walking speed: most walkers get through within the minute.
  CHECK(r.twinAtEnd > r.walkers / 2);
  CHECK(r.gpuAtEnd > r.walkers / 2);
}

TEST_CASE("the corridor ten times over (600 m, about 5,000 people): nobody leaves it in 60 s") {
  if (!test::haveSharedData(kTracked)) return;
  const CorridorRun r = runCorridor(600.0f, 60.0);
  CHECK(r.agents > 4000);
  CHECK(r.agents < 6500);
  checkNobodyLeaves(r);
  // Only walkers that start within a minute's walk of their end can be there (reported).
  CHECK(r.twinAtEnd > 0);
  CHECK(r.gpuAtEnd > 0);
}
