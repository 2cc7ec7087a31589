#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <span>

#include "core/error.h"
#include "core/math.h"
#include "core/rng.h"
#include "crowd/avoidance.h"
#include "crowd/avoidance_jobs.h"
#include "crowd/crowd_sim.h"
#include "crowd/obstacles.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"

using namespace throng;

namespace {

bool contains(const std::vector<std::string>& problems, const std::string& text) {
  for (const std::string& p : problems)
    if (p.find(text) != std::string::npos) return true;
  return false;
}

void addBox(crowd::Obstacles& o, glm::vec2 centre, glm::vec2 half) {
  const glm::vec2 box[] = {centre - half, centre + glm::vec2(half.x, -half.y), centre + half,
                           centre + glm::vec2(-half.x, half.y)};
  o.addPolyline(box, true);
}

// Thin walls (zero thickness) across the field, a corridor, boxes (convex corners), a U and a
// concave star (concave corners, two segments meeting at sharp angles) in a 100 m square.
crowd::Obstacles testWalls() {
  crowd::Obstacles o;
  const glm::vec2 thinA[] = {{-45.0f, -25.0f}, {10.0f, -25.0f}};
  const glm::vec2 thinB[] = {{-10.0f, 25.0f}, {45.0f, 25.0f}};
  o.addPolyline(thinA, false);
  o.addPolyline(thinB, false);
  const glm::vec2 corridorL[] = {{-20.0f, -10.0f}, {-20.0f, 10.0f}};
  const glm::vec2 corridorR[] = {{-17.0f, -10.0f}, {-17.0f, 10.0f}};
  o.addPolyline(corridorL, false);
  o.addPolyline(corridorR, false);
  for (int k = 0; k < 4; ++k) addBox(o, {-35.0f + 20.0f * float(k), 40.0f}, {2.0f, 1.5f});
  addBox(o, {0.0f, 0.0f}, {3.0f, 3.0f});
  const glm::vec2 u[] = {{20.0f, -5.0f}, {20.0f, 5.0f}, {30.0f, 5.0f}, {30.0f, -5.0f}};
  o.addPolyline(u, false);
  std::vector<glm::vec2> star;
  for (int k = 0; k < 10; ++k) {
    float angle = float(k) * 0.2f * kPi, r = k % 2 == 0 ? 6.0f : 2.0f;
    star.push_back(glm::vec2(25.0f, -35.0f) + r * glm::vec2(std::cos(angle), std::sin(angle)));
  }
  o.addPolyline(star, true);
  const glm::vec2 wedge[] = {{-30.0f, -45.0f}, {-35.0f, -35.0f}, {-25.0f, -35.0f}};  // acute V
  o.addPolyline(wedge, false);
  return o;
}

float wallDistance(const crowd::Obstacles& o, glm::vec2 p) {
  float d = std::numeric_limits<float>::max();
  for (const crowd::Segment& s : o.segments)
    d = std::min(d, glm::length(p - crowd::closestOnSegment(p, s.a, s.b)));
  return d;
}

struct Agents {
  crowd::Crowd crowd;
  std::vector<glm::vec4> goals, steer;
};

// `n` agents in the 100 m square, none within 0.5 m of a wall, each heading for the point
// opposite through the origin (so most walk into walls) at up to 1.5 m/s.
Agents fieldAgents(const crowd::Obstacles& walls, uint32_t n, uint64_t seed) {
  Agents a;
  a.crowd.resize(n);
  a.goals.resize(n);
  a.steer.resize(n);
  Rng rng(seed);
  for (uint32_t i = 0; i < n; ++i) {
    glm::vec2 p;
    do p = glm::vec2(rng.uniform(-48.0f, 48.0f), rng.uniform(-48.0f, 48.0f));
    while (wallDistance(walls, p) < 0.5f);
    glm::vec2 dir = glm::normalize(-p);
    a.crowd.placement[i] = glm::vec4(p.x, 0.0f, p.y, std::atan2(dir.x, dir.y));
    a.goals[i] = glm::vec4(-p, 1.5f, 1.0f);
    a.steer[i] = glm::vec4(dir, 1.0f, 0.0f);
  }
  return a;
}

crowd::SteerFrame frameOf(int s) {
  crowd::SteerFrame frame;
  frame.dt = 0.05f;
  frame.secondsLeft = 1.0f;
  frame.step = uint32_t(s);
  return frame;
}

// The CPU twin of one step: grid, steering with walls, advance, wall constraint.
void stepCpu(Agents& a, const crowd::AvoidanceParams& params, const crowd::WallGrid& walls, int s,
             std::vector<glm::vec4>& previous) {
  const auto n = uint32_t(a.crowd.size());
  crowd::Grid g =
      crowd::buildGridCpu(a.crowd.placement, a.steer, params.cellSize, crowd::gridTable(n));
  crowd::steerCpu(g, params, frameOf(s), a.crowd.placement, a.crowd.motion, a.goals, a.steer,
                  &walls);
  previous = a.crowd.placement;
  crowd::advanceCpu(a.crowd.placement, a.steer, a.goals, 0.05f);
  crowd::wallConstraintCpu(walls, params.radius, previous, a.crowd.placement, 0, n);
}

// The same on the GPU: buffers resident, one submit per step.
struct GpuWalls {
  gpu::Context& ctx = test::gpuContext();
  crowd::AvoidancePrograms programs{ctx};
  crowd::AvoidanceParams params;
  crowd::CrowdBuffers crowd;
  crowd::SteerBuffers agents;
  crowd::GridBuffers grid;
  crowd::WallBuffers walls;
  crowd::SavedPositions previous;
  uint32_t n = 0;
  bool fused = false;  // the advance constrains the move itself (no saved positions)

  GpuWalls(const Agents& a, const crowd::AvoidanceParams& p, const crowd::WallGrid& wallGrid)
      : params(p),
        crowd(crowd::uploadCrowd(ctx, a.crowd)),
        agents(crowd::uploadSteer(ctx, a.goals, a.steer)),
        grid(crowd::makeGridBuffers(ctx, uint32_t(a.crowd.size()), p.cellSize)),
        walls(crowd::uploadWalls(ctx, wallGrid)),
        previous(crowd::makeSavedPositions(ctx, uint32_t(a.crowd.size()))),
        n(uint32_t(a.crowd.size())) {}

  void upload(const Agents& a) {
    auto bytes = [](const std::vector<glm::vec4>& v) {
      return std::span<const uint8_t>(reinterpret_cast<const uint8_t*>(v.data()), v.size() * 16);
    };
    gpu::uploadBytes(ctx, crowd.placement, bytes(a.crowd.placement));
    gpu::uploadBytes(ctx, crowd.motion, bytes(a.crowd.motion));
    gpu::uploadBytes(ctx, agents.steer, bytes(a.steer));
  }

  void step(int s) {
    crowd::GridJob gridJob{&crowd, &agents, &grid};
    crowd::AvoidanceJob avoid{&crowd, &agents, &grid, params, frameOf(s), &walls};
    crowd::AdvanceJob advance{&crowd, &agents, 0.05f};
    crowd::WallConstraintJob constrain{&crowd, &previous, &walls, params.radius};
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      gridJob.record(cmd, programs);
      gpu::computeToComputeBarrier(cmd);
      avoid.record(cmd, programs);
      gpu::computeToComputeBarrier(cmd);
      if (fused) {
        crowd::AdvanceJob{&crowd, &agents, 0.05f, &walls, params.radius}.record(cmd, programs);
        return;
      }
      crowd::recordSavePositions(cmd, crowd, previous, 0, n);
      advance.record(cmd, programs);
      gpu::computeToComputeBarrier(cmd);
      constrain.record(cmd, programs);
    });
  }
  std::vector<glm::vec4> placement() const {
    return gpu::readback<glm::vec4>(ctx, crowd.placement, n);
  }
};

crowd::WallGrid binned(const crowd::Obstacles& o, const crowd::AvoidanceParams& params) {
  return crowd::binWallsFor(o, params);
}

}  // namespace

TEST_CASE("walls: polylines, polygons and a walkable raster become segments") {
  crowd::Obstacles o;
  const glm::vec2 line[] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {1.0f, 2.0f}};
  o.addPolyline(line, false);
  CHECK(o.segments.size() == 2);
  o.addPolyline(line, true);
  CHECK(o.segments.size() == 5);
  CHECK(o.segments.back().b == line[0]);
  CHECK_THROWS_WITH_AS(o.addPolyline(std::span(line, 2), true), doctest::Contains("at least 3"),
                       Error);

  // 3 x 3 walkable cells with the centre blocked: the outer square and the blocked cell's four
  // edges, each side merged into one straight run.
  crowd::WalkableGrid raster;
  raster.origin = {10.0f, 20.0f};
  raster.cellSize = 0.5f;
  raster.columns = raster.rows = 3;
  raster.walkable = {1, 1, 1, 1, 0, 1, 1, 1, 1};
  crowd::Obstacles fromRaster;
  fromRaster.addWalkableGrid(raster);
  REQUIRE(fromRaster.segments.size() == 8);
  float total = 0.0f;
  for (const crowd::Segment& s : fromRaster.segments) total += glm::length(s.b - s.a);
  CHECK(total == doctest::Approx(4 * 1.5f + 4 * 0.5f));
  CHECK(crowd::validateObstacles(fromRaster).empty());
  raster.walkable.pop_back();
  CHECK_THROWS_WITH_AS(fromRaster.addWalkableGrid(raster), doctest::Contains("one per cell"),
                       Error);
}

TEST_CASE("walls: invalid segments and budgets are reported") {
  crowd::Obstacles o;
  o.segments.push_back({{0.0f, 0.0f}, {std::nanf(""), 1.0f}});
  o.segments.push_back({{1.0f, 1.0f}, {1.0f, 1.0f}});
  o.segments.push_back({{0.0f, 0.0f}, {2.0e5f, 0.0f}});
  std::vector<std::string> problems = crowd::validateObstacles(o);
  CHECK(contains(problems, "wall segment 0"));
  CHECK(contains(problems, "wall segment 1 at (1, 1) is degenerate"));
  CHECK(contains(problems, "wall segment 2"));
  CHECK_THROWS_WITH_AS(crowd::binObstacles(o, 3.0f, 3.0f), doctest::Contains("walls:"), Error);

  crowd::Obstacles many;
  many.segments.assign(crowd::kMaxSegments + 1, {{0.0f, 0.0f}, {1.0f, 0.0f}});
  CHECK(contains(crowd::validateObstacles(many), "at most 1000000"));

  // A long wall over small cells needs more entries than a small budget allows.
  crowd::Obstacles longWall;
  const glm::vec2 line[] = {{0.0f, 0.0f}, {1000.0f, 0.0f}};
  longWall.addPolyline(line, false);
  CHECK_THROWS_WITH_AS(crowd::binObstacles(longWall, 1.0f, 3.0f, 1000), doctest::Contains("budget"),
                       Error);
  CHECK_NOTHROW(crowd::binObstacles(longWall, 1.0f, 3.0f, 100000));
}

TEST_CASE("walls: a point's cell lists every segment within reach (brute force)") {
  const crowd::Obstacles o = testWalls();
  const crowd::WallGrid g = crowd::binObstacles(o, 3.0f, 3.0f);
  REQUIRE(g.starts.size() == size_t(g.columns) * g.rows + 1);
  Rng rng(3);
  size_t near = 0;
  for (int k = 0; k < 20000; ++k) {
    glm::vec2 p(rng.uniform(-60.0f, 60.0f), rng.uniform(-60.0f, 60.0f));
    uint32_t cell = g.cellOf(p);
    for (size_t s = 0; s < o.segments.size(); ++s) {
      if (glm::length(p - crowd::closestOnSegment(p, o.segments[s].a, o.segments[s].b)) > 3.0f)
        continue;
      ++near;
      REQUIRE(cell != UINT32_MAX);
      bool listed = false;
      for (uint32_t e = g.starts[cell]; e < g.starts[cell + 1]; ++e) listed |= g.indices[e] == s;
      REQUIRE(listed);
    }
    // The cell's clearance is no farther than any listed segment is from a point in it.
    if (cell == UINT32_MAX) continue;
    for (uint32_t e = g.starts[cell]; e < g.starts[cell + 1]; ++e) {
      const crowd::Segment& s = o.segments[g.indices[e]];
      REQUIRE(g.clearance[cell] <= glm::length(p - crowd::closestOnSegment(p, s.a, s.b)));
    }
  }
  CHECK(near > 1000);  // the sample does test lists
}

// The violation check bins the segments itself; a brute-force count over every segment is the
// reference (crossing: the closed segments share a point, by orientations in double).
namespace {

crowd::WallViolations bruteForceViolations(std::span<const crowd::Segment> segments,
                                           std::span<const glm::vec4> previous,
                                           std::span<const glm::vec4> placement,
                                           float minDistance) {
  auto orient = [](glm::dvec2 o, glm::dvec2 u, glm::dvec2 v) {
    const double c = (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x);
    return c > 0.0 ? 1 : c < 0.0 ? -1 : 0;
  };
  crowd::WallViolations v;
  for (size_t i = 0; i < placement.size(); ++i) {
    const glm::dvec2 p(placement[i].x, placement[i].z), q(previous[i].x, previous[i].z);
    bool crossed = false, close = false;
    for (const crowd::Segment& s : segments) {
      const glm::vec2 pf(p);
      const float d = glm::length(pf - crowd::closestOnSegment(pf, s.a, s.b));
      v.closest = std::min(v.closest, d);
      close = close || d < minDistance;
      const glm::dvec2 a(s.a), b(s.b);
      crossed = crossed || (p != q && orient(q, p, a) != orient(q, p, b) &&
                            orient(a, b, q) != orient(a, b, p));
    }
    v.crossings += crossed;
    v.tooClose += close;
  }
  return v;
}

}  // namespace

TEST_CASE("walls: the violation check counts what a brute-force pass over every segment does") {
  crowd::Obstacles o = testWalls();
  Rng rng(11);
  // Long diagonals across the whole field and short ones anywhere, beside the test walls.
  for (int k = 0; k < 40; ++k) {
    const glm::vec2 a(rng.uniform(-50.0f, 50.0f), rng.uniform(-50.0f, 50.0f));
    const glm::vec2 b = k % 2 ? -a + glm::vec2(rng.uniform(-5.0f, 5.0f), 3.0f)
                              : a + glm::vec2(rng.uniform(-2.0f, 2.0f), rng.uniform(-2.0f, 2.0f));
    o.segments.push_back({a, b});
  }
  const crowd::WallGrid g = crowd::binObstacles(o, 2.0f, 1.0f);
  size_t crossings = 0, close = 0;
  for (int batch = 0; batch < 20; ++batch) {
    std::vector<glm::vec4> before, after;
    // Every fourth batch stands far beyond the walls, where the nearest wall is metres away.
    const bool far = batch % 4 == 3;
    for (int i = 0; i < 500; ++i) {
      glm::vec2 p(rng.uniform(-70.0f, 70.0f), rng.uniform(-70.0f, 70.0f));
      if (far) p = glm::normalize(p) * rng.uniform(80.0f, 200.0f);
      const glm::vec2 m = far ? glm::vec2(0.0f)
                              : glm::vec2(rng.uniform(-1.5f, 1.5f), rng.uniform(-1.5f, 1.5f));
      before.emplace_back(p.x, 0.0f, p.y, 0.0f);
      after.emplace_back(p.x + m.x, 0.0f, p.y + m.y, 0.0f);
    }
    after.back() = before.back();  // one agent that did not move
    const float minDistance = 0.1f * float(batch % 5);
    const crowd::WallViolations v = crowd::countWallViolations(g, before, after, minDistance);
    const crowd::WallViolations r = bruteForceViolations(o.segments, before, after, minDistance);
    CAPTURE(batch);
    CHECK(v.crossings == r.crossings);
    CHECK(v.tooClose == r.tooClose);
    CHECK(v.closest == r.closest);
    crossings += v.crossings;
    close += v.tooClose;
  }
  CHECK(crossings > 100);  // the sample does cross walls and come close to them
  CHECK(close > 100);
  // No walls: nothing to count.
  const std::vector<glm::vec4> one{glm::vec4(0.0f)};
  const crowd::WallViolations none = crowd::countWallViolations(crowd::WallGrid{}, one, one, 1.0f);
  CHECK(none.crossings == 0);
  CHECK(none.closest == crowd::kNoWallHit);
}

TEST_CASE("walls: a move through a thin wall or into a corner stops at the radius and slides") {
  crowd::Obstacles o;
  const glm::vec2 thin[] = {{0.0f, -5.0f}, {0.0f, 5.0f}};
  o.addPolyline(thin, false);
  const glm::vec2 corner[] = {{10.0f, 0.0f}, {20.0f, 0.0f}, {20.0f, 10.0f}};  // concave from inside
  o.addPolyline(corner, false);
  const crowd::WallGrid g = crowd::binObstacles(o, 3.0f, 3.0f);
  const float r = 0.3f;
  // Straight through the zero-thickness wall: stops r in front of it.
  glm::vec2 p = crowd::constrainMove(g, {-1.0f, 0.0f}, {1.0f, 0.0f}, r);
  CHECK(p.x == doctest::Approx(-r).epsilon(1e-3));
  CHECK(p.x < -r);
  // Obliquely: the motion along the wall survives (sliding).
  p = crowd::constrainMove(g, {-0.5f, 0.0f}, {0.5f, 1.0f}, r);
  CHECK(p.x < -r);
  CHECK(p.y == doctest::Approx(1.0f).epsilon(1e-3));
  // From just outside the radius, no step gets closer.
  p = crowd::constrainMove(g, {-r - 2e-4f, 0.0f}, {-r + 0.1f, 0.05f}, r);
  CHECK(p.x <= -r);
  // Into the concave corner (inside x < 20, z > 0): ends within neither wall's radius.
  p = crowd::constrainMove(g, {19.0f, 1.0f}, {21.0f, -1.0f}, r);
  CHECK(p.x <= 20.0f - r);
  CHECK(p.y >= r);
  // Around the outside of the corner's convex side: no crossing.
  p = crowd::constrainMove(g, {20.5f, -0.5f}, {19.5f, 0.5f}, r);
  CHECK(crowd::countWallViolations(g, std::vector{glm::vec4(20.5f, 0, -0.5f, 0)},
                                   std::vector{glm::vec4(p.x, 0.0f, p.y, 0.0f)}, r - 1e-3f)
            .crossings == 0);
  CHECK(wallDistance(o, p) >= r);
}

TEST_CASE("wall jobs: validity") {
  gpu::Context& ctx = test::gpuContext();
  crowd::AvoidancePrograms programs(ctx);
  Agents a = fieldAgents(testWalls(), 100, 1);
  crowd::CrowdBuffers buffers = crowd::uploadCrowd(ctx, a.crowd);
  crowd::SteerBuffers agents = crowd::uploadSteer(ctx, a.goals, a.steer);
  crowd::GridBuffers grid = crowd::makeGridBuffers(ctx, 100, {1.5f, 3.0f});
  crowd::WallBuffers walls = crowd::uploadWalls(ctx, crowd::binObstacles(testWalls(), 3.0f, 3.0f));
  crowd::SavedPositions saved = crowd::makeSavedPositions(ctx, 100);

  crowd::WallConstraintJob empty;
  std::vector<std::string> problems = empty.validate();
  CHECK(contains(problems, "'crowd' buffers are missing"));
  CHECK(contains(problems, "'previous'"));
  CHECK(contains(problems, "'walls' is missing"));

  crowd::WallConstraintJob job{&buffers, &saved, &walls, 0.3f};
  CHECK(job.validate().empty());
  CHECK(job.agents() == 100);
  job.firstCharacter = 60;
  job.count = 50;
  CHECK(contains(job.validate(), "run past the crowd's 100"));
  job.count = 40;
  CHECK(job.validate().empty());
  job.radius = 5.0f;
  CHECK(contains(job.validate(), "not more than the radius"));
  crowd::SavedPositions small = crowd::makeSavedPositions(ctx, 10);
  crowd::WallConstraintJob shortSaved{&buffers, &small, &walls, 0.3f};
  CHECK(contains(shortSaved.validate(), "saved positions hold 10"));
  CHECK_THROWS_AS(crowd::recordSavePositions(VK_NULL_HANDLE, buffers, small, 0, 100), Error);

  crowd::AvoidanceParams params;
  params.sensing = 4.0f;
  crowd::AvoidanceJob avoid{&buffers, &agents, &grid, params, frameOf(0), &walls};
  CHECK(contains(avoid.validate(), "less than the sensing distance 4"));
  params.sensing = 3.0f;
  avoid.params = params;
  CHECK(avoid.validate().empty());
}

TEST_CASE("walls: GPU vs CPU twin with walls, each policy") {
  const crowd::Obstacles o = testWalls();
  const Agents start = fieldAgents(o, 2000, 9);
  for (crowd::SteerPolicy policy :
       {crowd::SteerPolicy::None, crowd::SteerPolicy::Rule, crowd::SteerPolicy::Ttc}) {
    CAPTURE(crowd::steerPolicyName(policy));
    crowd::AvoidanceParams params;
    params.policy = policy;
    const crowd::WallGrid walls = binned(o, params);
    // TTC's forces amplify rounding step by step (test_avoidance.cpp), and the rule's discrete
    // choices do too once a wall contact differs by an ulp: their steps are compared on the
    // same input. Without a policy both run on their own.
    const bool resync = policy != crowd::SteerPolicy::None;
    Agents cpu = start;
    GpuWalls gpuRun(cpu, params, walls);
    std::vector<glm::vec4> previous;
    float worst = 0.0f;
    for (int s = 0; s < 20; ++s) {
      if (resync) gpuRun.upload(cpu);
      gpuRun.step(s);
      stepCpu(cpu, params, walls, s, previous);
      const std::vector<glm::vec4> placement = gpuRun.placement();
      for (size_t i = 0; i < placement.size(); ++i)
        worst = std::max(worst,
                         glm::length(glm::vec3(placement[i]) - glm::vec3(cpu.crowd.placement[i])));
    }
    MESSAGE(crowd::steerPolicyName(policy), ": max |GPU - CPU| position ", worst, " m");
    CHECK(worst <= 1e-4f);
  }
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

TEST_CASE("walls: the advance that constrains its own move matches the saved move + constraint") {
  const crowd::Obstacles o = testWalls();
  const Agents start = fieldAgents(o, 2000, 11);
  crowd::AvoidanceParams params;
  const crowd::WallGrid walls = binned(o, params);
  GpuWalls saved(start, params, walls), fused(start, params, walls);
  fused.fused = true;
  Agents cpu = start;
  std::vector<glm::vec4> previous;
  float apart = 0.0f, fromTwin = 0.0f;
  size_t moved = 0;
  for (int s = 0; s < 30; ++s) {
    fused.upload(cpu);  // both start every step from the twin's state
    saved.upload(cpu);
    fused.step(s);
    saved.step(s);
    const std::vector<glm::vec4> before = cpu.crowd.placement;
    stepCpu(cpu, params, walls, s, previous);
    const std::vector<glm::vec4> a = fused.placement(), b = saved.placement();
    for (size_t i = 0; i < a.size(); ++i) {
      apart = std::max(apart, glm::length(glm::vec3(a[i]) - glm::vec3(b[i])));
      fromTwin =
          std::max(fromTwin, glm::length(glm::vec3(a[i]) - glm::vec3(cpu.crowd.placement[i])));
      moved += a[i] != before[i];
    }
  }
  MESSAGE("fused vs saved move: ", apart, " m; vs the twin: ", fromTwin, " m; ", moved,
          " agent-steps moved");
  CHECK(apart == 0.0f);
  CHECK(fromTwin <= 1e-4f);
  CHECK(moved > 30000);
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

TEST_CASE("walls: 10000 agents over 300 steps never cross a wall nor come within its radius") {
  const crowd::Obstacles o = testWalls();
  const Agents start = fieldAgents(o, 10000, 4);
  crowd::AvoidanceParams params;
  params.policy = crowd::SteerPolicy::Ttc;
  const crowd::WallGrid walls = binned(o, params);
  const float tooClose = params.radius - 1e-3f;
  // The GPU with the anticipatory policy and with none (the constraint alone holds agents that
  // walk straight at the walls); the twin with the published rule.
  for (crowd::SteerPolicy policy : {crowd::SteerPolicy::Ttc, crowd::SteerPolicy::None}) {
    CAPTURE(crowd::steerPolicyName(policy));
    params.policy = policy;
    GpuWalls gpuRun(start, params, walls);
    std::vector<glm::vec4> before = start.crowd.placement;
    crowd::WallViolations total;
    float closest = std::numeric_limits<float>::max();
    for (int s = 0; s < 300; ++s) {
      gpuRun.step(s);
      std::vector<glm::vec4> after = gpuRun.placement();
      crowd::WallViolations v = crowd::countWallViolations(walls, before, after, tooClose);
      total.crossings += v.crossings;
      total.tooClose += v.tooClose;
      closest = std::min(closest, v.closest);
      before = std::move(after);
    }
    MESSAGE("GPU ", crowd::steerPolicyName(policy), ": closest approach to a wall ", closest,
            " m (radius ", params.radius, ")");
    CHECK(total.crossings == 0);
    CHECK(total.tooClose == 0);
    // The scene does press agents against the walls.
    CHECK(closest < params.radius + 0.01f);
  }
  params.policy = crowd::SteerPolicy::Rule;
  Agents cpu = start;
  std::vector<glm::vec4> previous;
  crowd::WallViolations total;
  for (int s = 0; s < 300; ++s) {
    stepCpu(cpu, params, walls, s, previous);
    crowd::WallViolations v =
        crowd::countWallViolations(walls, previous, cpu.crowd.placement, tooClose);
    total.crossings += v.crossings;
    total.tooClose += v.tooClose;
    total.closest = std::min(total.closest, v.closest);
  }
  MESSAGE("twin published: closest approach to a wall ", total.closest, " m");
  CHECK(total.crossings == 0);
  CHECK(total.tooClose == 0);
  CHECK(total.closest < params.radius + 0.01f);
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

TEST_CASE("walls: agents heading past a wall's end or a box go around it and arrive") {
  crowd::Obstacles o;
  const glm::vec2 wall[] = {{0.0f, -20.0f}, {0.0f, 0.0f}};  // its end at the origin
  o.addPolyline(wall, false);
  addBox(o, {30.0f, 0.0f}, {2.0f, 2.0f});
  // Starts left of each obstacle, goals right of it beyond the wall's end or the box's top
  // face: the straight line runs into the wall below its end, or into the box's near face.
  std::vector<glm::vec2> starts, goals;
  for (float dz : {-1.5f, -0.8f, -0.3f}) {
    starts.push_back({-3.0f, dz}), goals.push_back({3.0f, dz + 2.0f});
    starts.push_back({26.0f, 1.0f + dz}), goals.push_back({34.0f, 4.0f + dz});
  }
  Agents a;
  const auto n = uint32_t(starts.size());
  a.crowd.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    a.crowd.placement[i] = glm::vec4(starts[i].x, 0.0f, starts[i].y, 0.5f * kPi);
    a.goals.push_back(glm::vec4(goals[i], 1.3f, 1.0f));
    a.steer.push_back(glm::vec4(1.0f, 0.0f, 1.0f, 0.0f));
  }
  const int kSteps = 600;  // 30 s for at most 8.2 m
  for (crowd::SteerPolicy policy : {crowd::SteerPolicy::Ttc, crowd::SteerPolicy::Rule}) {
    CAPTURE(crowd::steerPolicyName(policy));
    crowd::AvoidanceParams params;
    params.policy = policy;
    const crowd::WallGrid walls = binned(o, params);
    Agents cpu = a;
    GpuWalls gpuRun(a, params, walls);
    std::vector<glm::vec4> previous;
    for (int s = 0; s < kSteps; ++s) {
      stepCpu(cpu, params, walls, s, previous);
      gpuRun.step(s);
    }
    const std::vector<glm::vec4> placement = gpuRun.placement();
    // The three goals beyond each obstacle lie 0.5–0.7 m apart, closer than two safe radii:
    // anticipatory agents that arrive settle where their pushes balance, up to about a radius
    // off their own goal (where the density slows them decides which settles where).
    const float near = policy == crowd::SteerPolicy::Ttc ? 0.75f : 0.5f;
    for (uint32_t i = 0; i < n; ++i) {
      CAPTURE(i);
      CHECK(glm::length(glm::vec2(cpu.crowd.placement[i].x, cpu.crowd.placement[i].z) - goals[i]) <
            near);
      CHECK(glm::length(glm::vec2(placement[i].x, placement[i].z) - goals[i]) < near);
    }
  }
}
