// Secondary graph on the toy garment: initialisation covers every primary edge, no dead end
// ever remains, merges join states of the same primary node, the queue is ordered by error,
// undoing a merge restores the exact edges, and expansions follow the simulator exactly.
#include <doctest/doctest.h>

#include <algorithm>

#include "core/error.h"
#include "explore_fixtures.h"
#include "secondary/offline/toy_garment.h"

using namespace throng;
using namespace throng::secondary;
using namespace throng::secondary::fixtures;

namespace {
// The invariants the issue lists, checked on the whole graph.
void checkInvariants(const SecondaryGraph& g, const PrimaryGraph& primary) {
  validateGraph(g, primary);  // throws on a dead end or a merge into another primary node
  CHECK(countDeadEnds(g) == 0);
  for (uint32_t s = 0; s < g.stateCount(); ++s)
    for (uint32_t k = 0; k < g.edgeCount(s); ++k) {
      const SecondaryEdge& e = g.edge(s, k);
      REQUIRE(e.target != kNoState);
      REQUIRE(g.stateNode[e.target] == primary.successors[g.stateNode[s]][k]);
    }
  float previous = INFINITY;
  for (const MergeKey& m : g.queue) {
    REQUIRE(m.error <= previous);
    REQUIRE(g.edge(m.state, m.edge).isMerge);
    REQUIRE(g.edge(m.state, m.edge).error == m.error);
    previous = m.error;
  }
  CHECK(g.queue.size() == countMerges(g));
}
}  // namespace

TEST_CASE("toy primary graph and step are well formed and deterministic") {
  const Garment garment = toyGarment();
  const PrimaryGraph& p = *garment.primary;
  CHECK(p.nodes.size() == 14);
  const ClothState s0 = initialClothState(garment);
  CHECK(s0.positions.size() == garment.mesh->vertexCount());
  const ClothState a = garment.step(s0, 0, 1);
  const ClothState b = garment.step(s0, 0, 1);
  CHECK(sameBits(a.positions, b.positions));
  CHECK(sameBits(a.velocities, b.velocities));
  CHECK(a.positions[0] == p.pose(1)[1].position);  // pinned to the neck
  CHECK_THROWS_AS(garment.step(s0, 0, 5), Error);  // not a primary edge
}

TEST_CASE("initialisation simulates every reachable primary edge once and leaves no dead end") {
  const Garment garment = toyGarment();
  const PrimaryGraph& p = *garment.primary;
  const SecondaryGraph g = initializeToy(garment);
  checkInvariants(g, p);
  size_t primaryEdges = 0;
  for (const auto& s : p.successors) primaryEdges += s.size();
  CHECK(g.stateCount() == p.nodes.size());  // one state per node: the first frame to reach it
  CHECK(g.simulatedSteps == primaryEdges);
  for (uint32_t n = 0; n < p.nodes.size(); ++n) CHECK(g.statesAtNode[n].size() == 1);
  CHECK(g.queue.size() == primaryEdges - (p.nodes.size() - 1));  // edges outside the BFS tree
  CHECK(maxMergeError(g) > 0.0f);
  REQUIRE(g.history.size() == 1);
  CHECK(g.history[0].maxMergeError == maxMergeError(g));

  const PlaybackGraph pb = playbackGraph(g);
  CHECK(pb.stateCount() == g.stateCount());
  CHECK(pb.firstEdge == g.firstEdge);
  CHECK(size_t(std::count(pb.edgeIsMerge.begin(), pb.edgeIsMerge.end(), 1)) == g.queue.size());
}

TEST_CASE("no dead end and an ordered queue after every expansion") {
  const Garment garment = toyGarment();
  const PrimaryGraph& p = *garment.primary;
  SecondaryGraph g = initializeToy(garment);
  ThreadedRunner runner(p, garment.step, 1);
  ExploreHooks hooks;
  uint64_t calls = 0;
  hooks.progress = [&](const SecondaryGraph& now) {
    ++calls;
    checkInvariants(now, p);
    CHECK(now.history.back().expansions == now.expansions);
    CHECK(now.history.back().maxMergeError == maxMergeError(now));
  };
  ExpandOptions options;
  options.depth = 2;
  const ExploreStop stop =
      exploreGraph(g, p, runner, toyMetric(garment), options, {40, 0.0, 0.0f}, hooks);
  CHECK(stop == ExploreStop::Expansions);
  CHECK(calls == 40);
  CHECK(g.expansions == 40);
  CHECK(g.history.size() == 41);
  CHECK(g.history.back().maxMergeError < g.history.front().maxMergeError);  // exploring helps
}

TEST_CASE("undoing a merge restores the exact edges, and an expansion follows the simulator") {
  const Garment garment = toyGarment();
  const PrimaryGraph& p = *garment.primary;
  SecondaryGraph g = initializeToy(garment);
  const SecondaryGraph before = g;
  const MergeKey worst = *g.queue.begin();
  const uint32_t target = g.edge(worst.state, worst.edge).target;

  undoMerge(g, worst.state, worst.edge);
  CHECK(g.edge(worst.state, worst.edge).target == kNoState);
  CHECK(countDeadEnds(g) == 1);
  CHECK(g.queue.size() == before.queue.size() - 1);
  CHECK_THROWS_AS(validateGraph(g, p), Error);
  mergeEdge(g, p, worst.state, worst.edge, target, worst.error);
  CHECK(sameEdges(g, before));
  CHECK(g.queue.size() == before.queue.size());
  CHECK(maxMergeError(g) == maxMergeError(before));

  // Merging into a state of another primary node is refused.
  undoMerge(g, worst.state, worst.edge);
  const uint32_t wrongNode =
      (p.successors[g.stateNode[worst.state]][worst.edge] + 1) % uint32_t(p.nodes.size());
  CHECK_THROWS_AS(mergeEdge(g, p, worst.state, worst.edge, g.statesAtNode[wrongNode][0], 0.1f),
                  Error);

  // Expanding the worst merge: its new state is exactly the simulator's step from the source.
  ExpandOptions options;
  options.depth = 1;
  const ExpansionResult result =
      simulateExpansion(p, garment.step, expansionTask(g, options, worst));
  applyExpansion(g, p, toyMetric(garment), worst, result);
  validateGraph(g, p);
  const uint32_t fresh = g.edge(worst.state, worst.edge).target;
  CHECK(fresh == before.stateCount());
  CHECK_FALSE(g.edge(worst.state, worst.edge).isMerge);
  const ClothState expected = garment.step(clothState(before, worst.state),
                                           before.stateNode[worst.state], g.stateNode[fresh]);
  CHECK(sameBits(clothState(g, fresh).positions, expected.positions));
  CHECK(sameBits(clothState(g, fresh).velocities, expected.velocities));
  CHECK(g.simulatedSteps == before.simulatedSteps + result.simulatedSteps());
}

TEST_CASE("the merge error is the L-infinity distance plus the garment term") {
  ClothState a{{{0, 0, 0}, {1, 0, 0}}, {{0, 0, 0}, {0, 0, 0}}};
  ClothState b = a;
  b.positions[1].y = 0.03f;  // 3 cm
  b.velocities[0].x = 0.5f;  // 0.5 m/s × 0.1 s = 5 cm
  MergeMetric metric{0.1f, {}};
  CHECK(mergeError(metric, view(a), view(b), 0) == doctest::Approx(0.05f));
  metric.velocityScale = 0.02f;
  CHECK(mergeError(metric, view(a), view(b), 0) == doctest::Approx(0.03f));
  metric.garment = [](FrameView, FrameView, uint32_t) { return 1.0f; };
  CHECK(mergeError(metric, view(a), view(b), 0) == doctest::Approx(1.03f));
  CHECK(linfDistance(view(a), view(b), 0.02f, 0.01f) >
        0.01f);  // early exit still exceeds the bound

  // The shoulder term counts vertices in front of the chest plane.
  const Garment garment = toyGarment();
  const GarmentTerm term = shoulderSideTerm(garment.primary, {1}, 0.5f);
  ClothState front = a, back = a;
  const float z = garment.primary->pose(0)[1].position.z;
  front.positions = {{0, 0, z + 0.1f}, {0, 0, z + 0.1f}};
  back.positions = {{0, 0, z - 0.1f}, {0, 0, z + 0.1f}};
  CHECK(term(view(front), view(back), 0) == doctest::Approx(0.25f));
  CHECK(term(view(front), view(front), 0) == 0.0f);
}

TEST_CASE("task and result messages round trip") {
  const Garment garment = toyGarment();
  const SecondaryGraph g = initializeToy(garment);
  ExpandOptions options;
  options.depth = 2;
  const ExpansionTask task = expansionTask(g, options, *g.queue.begin());
  const ExpansionTask t2 = decodeTask(encodeTask(task));
  CHECK(t2.node == task.node);
  CHECK(t2.edge == task.edge);
  CHECK(t2.depth == 2);
  CHECK(t2.maxStates == task.maxStates);
  CHECK(sameBits(t2.start.positions, task.start.positions));
  const ExpansionResult r = simulateExpansion(*garment.primary, garment.step, task);
  CHECK(r.states.size() >= 3);
  const ExpansionResult r2 = decodeResult(encodeResult(r));
  REQUIRE(r2.states.size() == r.states.size());
  REQUIRE(r2.deadEnds.size() == r.deadEnds.size());
  for (size_t i = 0; i < r.states.size(); ++i) {
    CHECK(r2.states[i].node == r.states[i].node);
    CHECK(r2.states[i].parent == r.states[i].parent);
    CHECK(sameBits(r2.states[i].cloth.velocities, r.states[i].cloth.velocities));
  }
  for (size_t i = 0; i < r.deadEnds.size(); ++i) {
    CHECK(r2.deadEnds[i].state == r.deadEnds[i].state);
    CHECK(sameBits(r2.deadEnds[i].cloth.positions, r.deadEnds[i].cloth.positions));
  }
  std::vector<uint8_t> bad = encodeResult(r);
  bad[bad.size() / 2] ^= 1;
  CHECK_THROWS_WITH_AS(decodeResult(bad), doctest::Contains("checksum mismatch"), Error);
}
