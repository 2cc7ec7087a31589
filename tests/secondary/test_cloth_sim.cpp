// The XPBD cloth: settling, collisions, determinism, and the cape in the wind of running.
#include <doctest/doctest.h>

#include <chrono>
#include <cstring>
#include <future>
#include <thread>

#include "core/error.h"
#include "core/math.h"
#include "primary_fixtures.h"
#include "secondary/offline/cloth_mesh.h"
#include "secondary/offline/cloth_sim.h"

using namespace throng;
using namespace throng::secondary;

namespace {

struct Energies {
  double kinetic = 0.0;
  double meanHeight = 0.0;  // mass-weighted mean y (potential energy / (M g))
};

Energies energies(const ClothState& state, const std::vector<float>& mass) {
  Energies e;
  double total = 0.0;
  for (size_t i = 0; i < mass.size(); ++i) {
    e.kinetic += 0.5 * mass[i] * double(glm::dot(state.velocities[i], state.velocities[i]));
    e.meanHeight += mass[i] * double(state.positions[i].y);
    total += mass[i];
  }
  e.meanHeight /= total;
  return e;
}

// Natural successors from `node` for `frames` frames; calls visit(state, toNode) after each.
template <typename Visit>
uint32_t walk(const StepFunction& step, const PrimaryGraph& graph, ClothState& state, uint32_t node,
              uint32_t frames, Visit&& visit) {
  for (uint32_t f = 0; f < frames; ++f) {
    const uint32_t next = naturalSuccessor(graph, node);
    state = step(state, node, next);
    node = next;
    visit(state, node);
  }
  return node;
}

bool sameBits(const ClothState& a, const ClothState& b) {
  return a.positions.size() == b.positions.size() && a.velocities.size() == b.velocities.size() &&
         std::memcmp(a.positions.data(), b.positions.data(),
                     a.positions.size() * sizeof(glm::vec3)) == 0 &&
         std::memcmp(a.velocities.data(), b.velocities.data(),
                     a.velocities.size() * sizeof(glm::vec3)) == 0;
}

std::shared_ptr<const ClothMesh> defaultCape() {
  static const auto cape = std::make_shared<const ClothMesh>(makeCape(*test::defaultRunGraph()));
  return cape;
}

glm::vec2 meanZ(const ClothState& state, const ClothMesh& mesh) {  // (pinned, free)
  glm::vec2 sum(0.0f), count(0.0f);
  for (uint32_t i = 0; i < mesh.vertexCount(); ++i) {
    const int k = std::find(mesh.pinnedVertices.begin(), mesh.pinnedVertices.end(), i) !=
                          mesh.pinnedVertices.end()
                      ? 0
                      : 1;
    sum[k] += state.positions[i].z;
    count[k] += 1.0f;
  }
  return sum / count;
}

}  // namespace

TEST_CASE("a square cloth pinned along one edge swings down and settles hanging straight") {
  const auto graph = test::standingGraph();
  const float size = 0.6f;
  const auto square = std::make_shared<const ClothMesh>(makeSquareCloth(16, size));
  ClothSimOptions options;
  options.ground = false;
  const StepFunction step = makeClothStepFunction(graph, square, options);
  const std::vector<float> mass = vertexMasses(*square, options.areaDensity);
  ClothState state = restState(*square, *graph, 0);
  CHECK(energies(state, mass).meanHeight == 0.0);
  double peak = 0.0;
  walk(step, *graph, state, 0, 30,
       [&](const ClothState& s, uint32_t) { peak = std::max(peak, energies(s, mass).kinetic); });
  walk(step, *graph, state, 0, 270, [](const ClothState&, uint32_t) {});
  const Energies settled = energies(state, mass);
  const double totalMass = options.areaDensity * size * size;
  MESSAGE("square: peak kinetic ", peak, " J, after 10 s ", settled.kinetic, " J, mean height ",
          settled.meanHeight, " m (hanging straight: ", -0.5 * size, ")");
  // It did fall (the swing had real kinetic energy) …
  CHECK(peak > 0.1 * totalMass * 9.81 * 0.5 * size);
  // … and has come to rest, hanging straight down within 2% of its length.
  CHECK(settled.kinetic < 2e-6 * totalMass * 9.81 * size);
  CHECK(settled.meanHeight == doctest::Approx(-0.5 * size).epsilon(0.02));
  for (uint32_t i = 16; i < square->vertexCount(); ++i)
    CHECK(std::abs(state.positions[i].z) < 0.02f * size);
}

TEST_CASE("internal damping stills the swing of a cloth but not its motion as a whole") {
  const auto graph = test::standingGraph();
  const auto square = std::make_shared<const ClothMesh>(makeSquareCloth(16, 0.6f));
  const std::vector<float> mass = vertexMasses(*square, 0.25f);
  auto swingAfter = [&](float damping, uint32_t frames) {
    ClothSimOptions options;
    options.ground = false;
    options.internalDamping = damping;
    const StepFunction step = makeClothStepFunction(graph, square, options);
    ClothState state = restState(*square, *graph, 0);
    walk(step, *graph, state, 0, frames, [](const ClothState&, uint32_t) {});
    return energies(state, mass).kinetic;
  };
  // Half a second into the fall from horizontal, the damped cloth swings slower, and after two
  // seconds it is far closer to rest.
  const double free05 = swingAfter(0.0f, 15), damped05 = swingAfter(150.0f, 15);
  const double free2 = swingAfter(0.0f, 60), damped2 = swingAfter(150.0f, 60);
  MESSAGE("kinetic energy at 0.5 s: ", free05, " J undamped, ", damped05,
          " J damped; at 2 s: ", free2, " J, ", damped2, " J");
  CHECK(damped05 < 0.9 * free05);
  CHECK(damped2 < 0.2 * free2);

  // A free cloth moving as one body keeps its velocity exactly: damping acts on relative
  // velocity only.
  ClothMesh loose = *square;
  loose.pinnedVertices.clear();
  loose.pinJoints.clear();
  loose.pinOffsets.clear();
  ClothSimOptions options;
  options.ground = false;
  options.gravity = glm::vec3(0.0f);
  options.drag = 0.0f;
  options.longRangeAttachments = false;
  options.internalDamping = 1000.0f;
  const StepFunction step =
      makeClothStepFunction(graph, std::make_shared<const ClothMesh>(loose), options);
  ClothState state = restState(loose, *graph, 0);
  for (glm::vec3& p : state.positions) p += glm::vec3(0.0f, 3.0f, 0.0f);  // clear of the body
  for (glm::vec3& v : state.velocities) v = glm::vec3(0.3f, 0.1f, -0.2f);
  walk(step, *graph, state, 0, 10, [](const ClothState&, uint32_t) {});
  for (const glm::vec3& v : state.velocities)
    CHECK(glm::length(v - glm::vec3(0.3f, 0.1f, -0.2f)) < 1e-4f);

  CHECK_THROWS_AS(makeClothStepFunction(graph, square, ClothSimOptions{.internalDamping = -1.0f}),
                  Error);
}

TEST_CASE("no cloth vertex ends a step inside a body capsule while running and changing speed") {
  const auto graph = test::defaultRunGraph();
  const auto cape = defaultCape();
  const ClothSimOptions options;
  const StepFunction step = makeClothStepFunction(graph, cape, options);
  const std::vector<Capsule> capsules = resolveCapsules(*graph, options.capsules);
  REQUIRE(capsules.size() == 18);
  std::vector<bool> pinned(cape->vertexCount(), false);
  for (uint32_t v : cape->pinnedVertices) pinned[v] = true;
  float closest = 1.0f;
  uint32_t inside = 0;
  auto check = [&](const ClothState& s, uint32_t node) {
    for (const CapsuleShape& c : capsulesAt(*graph, capsules, node))
      for (uint32_t i = 0; i < cape->vertexCount(); ++i) {
        if (pinned[i]) continue;
        const float gap = segmentDistance(s.positions[i], c.a, c.b) - c.radius;
        closest = std::min(closest, gap);
        inside += gap < 0.0f ? 1u : 0u;
      }
  };
  ClothState state = restState(*cape, *graph, 0);
  // Slow run for two cycles, then the cycle end into the fastest bucket, then two fast cycles.
  uint32_t node = walk(step, *graph, state, 0, 2 * 23 - 1, check);
  REQUIRE(graph->nodes[node].frame == 22);
  const uint32_t fast = test::cycleStart(*graph, 20);
  state = step(state, node, fast);
  check(state, fast);
  walk(step, *graph, state, fast, 40, check);
  MESSAGE("closest free vertex to a capsule surface: ", closest, " m");
  CHECK(inside == 0);
}

TEST_CASE("cloth steps are deterministic, also from two threads at once") {
  const auto graph = test::defaultRunGraph();
  const StepFunction step = makeClothStepFunction(graph, defaultCape(), ClothSimOptions{});
  const uint32_t start = test::cycleStart(*graph, 14);
  const ClothState initial = restState(*defaultCape(), *graph, start);
  auto run = [&] {
    ClothState s = initial;
    walk(step, *graph, s, start, 30, [](const ClothState&, uint32_t) {});
    return s;
  };
  const auto t0 = std::chrono::steady_clock::now();
  const ClothState serial = run();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  MESSAGE("cape of ", defaultCape()->vertexCount(), " vertices: ", 30.0 / seconds,
          " frames/s on one thread");
  CHECK(sameBits(serial, run()));
  // std::async carries a failure in either run back here as an exception.
  std::future<ClothState> fa = std::async(std::launch::async, run);
  std::future<ClothState> fb = std::async(std::launch::async, run);
  const ClothState a = fa.get(), b = fb.get();
  CHECK(sameBits(serial, a));
  CHECK(sameBits(serial, b));
  // And it moved: the state is not the initial one.
  CHECK_FALSE(sameBits(serial, initial));
}

TEST_CASE("running forward fast, the cape streams out behind, further than on a treadmill") {
  const auto graph = test::defaultRunGraph();
  auto treadmill =
      std::make_shared<PrimaryGraph>(*graph);  // the same poses without travel: no wind
  for (auto& steps : treadmill->rootStep)
    for (glm::vec3& s : steps) s = glm::vec3(0.0f);
  const uint32_t fast = test::cycleStart(*graph, 20);
  auto settleOn = [&](std::shared_ptr<const PrimaryGraph> g) {
    const StepFunction step = makeClothStepFunction(g, defaultCape(), ClothSimOptions{});
    return settleCloth(step, *g, restState(*defaultCape(), *g, fast), fast, 60);
  };
  const glm::vec2 running = meanZ(settleOn(graph), *defaultCape());
  const glm::vec2 standing = meanZ(settleOn(treadmill), *defaultCape());
  MESSAGE("mean z running fast: pinned ", running[0], ", free ", running[1],
          "; on a treadmill: free ", standing[1]);
  CHECK(running[1] < running[0]);
  CHECK(running[1] < standing[1] - 0.05f);
}

TEST_CASE("rest state, settling and bad calls") {
  const auto graph = test::defaultRunGraph();
  const auto cape = defaultCape();
  const uint32_t node = test::cycleStart(*graph, 10) + 5;
  const ClothState rest = restState(*cape, *graph, node);
  REQUIRE(rest.positions.size() == cape->vertexCount());
  // Pinned vertices sit where their joints hold them; everything moves with the character.
  for (size_t k = 0; k < cape->pinnedVertices.size(); ++k) {
    const NodeJoint& joint = graph->pose(node)[cape->pinJoints[k]];
    const glm::vec3 expected = joint.position + quatRotate(joint.rotation, cape->pinOffsets[k]);
    CHECK(glm::length(rest.positions[cape->pinnedVertices[k]] - expected) < 1e-6f);
  }
  const glm::vec3 velocity = graph->rootStep[node][0] / graph->frameTime;
  CHECK(rest.velocities.front() == velocity);
  CHECK(velocity.z > 2.0f);

  const StepFunction step = makeClothStepFunction(graph, cape, ClothSimOptions{});
  const ClothState settled = settleCloth(step, *graph, rest, node, 10);
  CHECK(settled.positions.size() == rest.positions.size());
  CHECK_THROWS_WITH_AS(step(rest, node, node + 2), doctest::Contains("no edge"), Error);
  ClothState wrong = rest;
  wrong.velocities.pop_back();
  CHECK_THROWS_AS(step(wrong, node, node + 1), Error);
  CHECK_THROWS_AS(makeClothStepFunction(graph, cape, ClothSimOptions{.substeps = 0}), Error);
  ClothMesh broken = *cape;
  broken.pinJoints[0] = 99;
  CHECK_THROWS_AS(
      makeClothStepFunction(graph, std::make_shared<const ClothMesh>(broken), ClothSimOptions{}),
      Error);
}
