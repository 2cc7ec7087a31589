// The crowd's primary motion graph: nodes per (speed bucket, frame), next-frame edges, bucket
// changes only at cycle ends, and pruning to the strongly connected part.
#include <doctest/doctest.h>

#include <deque>

#include "anim/reference_synth.h"
#include "core/error.h"
#include "primary_fixtures.h"
#include "synth/motion_cache.h"

using namespace throng;
using namespace throng::secondary;

namespace {

// Nodes reached from `start` along successors (or predecessors when reversed): plain BFS,
// independent of the Tarjan code under test.
std::vector<bool> reached(const PrimaryGraph& graph, uint32_t start, bool reversed) {
  std::vector<std::vector<uint32_t>> edges(graph.nodes.size());
  for (uint32_t v = 0; v < graph.nodes.size(); ++v)
    for (uint32_t w : graph.successors[v])
      (reversed ? edges[w] : edges[v]).push_back(reversed ? v : w);
  std::vector<bool> seen(graph.nodes.size(), false);
  std::deque<uint32_t> queue{start};
  seen[start] = true;
  while (!queue.empty()) {
    uint32_t v = queue.front();
    queue.pop_front();
    for (uint32_t w : edges[v])
      if (!seen[w]) {
        seen[w] = true;
        queue.push_back(w);
      }
  }
  return seen;
}

void checkNoDeadEndAndConnected(const PrimaryGraph& graph) {
  for (uint32_t v = 0; v < graph.nodes.size(); ++v)
    REQUIRE_MESSAGE(!graph.successors[v].empty(), "node ", v);
  const std::vector<bool> forward = reached(graph, 0, false), backward = reached(graph, 0, true);
  for (uint32_t v = 0; v < graph.nodes.size(); ++v) {
    REQUIRE_MESSAGE(forward[v], "node ", v, " is not reachable from node 0");
    REQUIRE_MESSAGE(backward[v], "node 0 is not reachable from node ", v);
  }
  CHECK(isStronglyConnected(graph));
}

PrimaryGraph tinyGraph(std::vector<std::vector<uint32_t>> successors) {
  PrimaryGraph graph;
  graph.jointCount = 1;
  graph.parents = {-1};
  graph.jointNames = {"Root"};
  for (uint32_t v = 0; v < successors.size(); ++v) {
    graph.nodes.push_back({0, 0, v});
    graph.poses.push_back({glm::vec3(float(v)), glm::vec4(0, 0, 0, 1)});
    graph.rootStep.push_back({});
    for (uint32_t w : successors[v])
      graph.rootStep.back().push_back(glm::vec3(float(v), float(w), 0.0f));
  }
  graph.successors = std::move(successors);
  return graph;
}

}  // namespace

TEST_CASE(
    "pruning keeps the largest strongly connected component and drops dead ends and sources") {
  // {0,1,2} is a cycle; 3 is a dead end after 2; 4 only leads into the cycle; {5,6} is a
  // smaller cycle reached from 0.
  PrimaryGraph graph = tinyGraph({{1, 5}, {2}, {0, 3}, {}, {0}, {6}, {5}});
  CHECK_FALSE(isStronglyConnected(graph));
  const std::vector<int32_t> remap = pruneToStronglyConnected(graph);
  CHECK(remap == std::vector<int32_t>{0, 1, 2, -1, -1, -1, -1});
  REQUIRE(graph.nodes.size() == 3);
  CHECK(graph.successors == std::vector<std::vector<uint32_t>>{{1}, {2}, {0}});
  // Steps travel with their edges; poses with their nodes.
  CHECK(graph.rootStep[0] == std::vector<glm::vec3>{glm::vec3(0, 1, 0)});
  CHECK(graph.rootStep[2] == std::vector<glm::vec3>{glm::vec3(2, 0, 0)});
  CHECK(graph.poses[2].position == glm::vec3(2.0f));
  checkNoDeadEndAndConnected(graph);
}

TEST_CASE("pruning: a later, larger component wins and a graph without any cycle is an error") {
  PrimaryGraph graph = tinyGraph({{1}, {0}, {3}, {4}, {2}, {5}});  // {0,1} < {2,3,4}; 5 self-loop
  const std::vector<int32_t> remap = pruneToStronglyConnected(graph);
  CHECK(remap == std::vector<int32_t>{-1, -1, 0, 1, 2, -1});
  CHECK(graph.nodes[0].frame == 2);
  checkNoDeadEndAndConnected(graph);

  PrimaryGraph chain = tinyGraph({{1}, {2}, {}});
  CHECK_THROWS_AS(pruneToStronglyConnected(chain), Error);
  PrimaryGraph broken = tinyGraph({{7}});
  CHECK_THROWS_WITH_AS(pruneToStronglyConnected(broken), doctest::Contains("successor 7"), Error);
}

TEST_CASE(
    "the run graph has one node per speed bucket and cycle frame, and is strongly connected") {
  const PrimaryGraph& graph = *test::defaultRunGraph();
  const anim::MotionPair pair =
      anim::makeMotionPair(test::defaultClips().slow, test::defaultClips().fast);
  const uint32_t buckets = synth::speedBucketCount(test::kTestBucketWidth);
  REQUIRE(buckets == 21);
  CHECK(graph.jointCount == 25);
  CHECK(graph.jointNames[5] == "Neck");
  CHECK(graph.frameTime == doctest::Approx(1.0 / 30.0));
  size_t expected = 0;
  for (uint32_t b = 0; b < buckets; ++b) {
    const float w = synth::bucketSpeed(b, test::kTestBucketWidth);
    const uint32_t frames = runCycleFrames(pair, w, graph.frameTime);
    CHECK(frames == std::max(2l, std::lround(runCycleDuration(pair, w) / graph.frameTime)));
    const uint32_t first = test::cycleStart(graph, b);
    REQUIRE(first != UINT32_MAX);
    glm::vec3 travel(0.0f);
    for (uint32_t f = 0; f < frames; ++f) {
      const uint32_t node = first + f;
      REQUIRE(graph.nodes[node].bucket == b);
      REQUIRE(graph.nodes[node].frame == f);
      const bool cycleEnd = f + 1 == frames;
      // w changes only at a cycle end, to any bucket.
      REQUIRE(graph.successors[node].size() == (cycleEnd ? buckets : 1u));
      if (!cycleEnd) CHECK(graph.successors[node][0] == node + 1);
      if (cycleEnd)
        for (uint32_t to = 0; to < buckets; ++to)
          CHECK(graph.successors[node][to] == test::cycleStart(graph, to));
      CHECK(naturalSuccessor(graph, node) == (cycleEnd ? first : node + 1));
      travel += graph.rootStep[node][0];
    }
    // One cycle of steps moves the character as far as the synthesizer does in one cycle.
    const glm::vec3 cycle = pair.slow.cycleTravel * (1.0f - w) + pair.fast.cycleTravel * w;
    CHECK(travel.z == doctest::Approx(cycle.z).epsilon(1e-4));
    CHECK(travel.y == 0.0f);
    expected += frames;
  }
  CHECK(graph.nodes.size() == expected);
  checkNoDeadEndAndConnected(graph);
}

TEST_CASE("run graph poses are the synthesizer's character-space poses") {
  const PrimaryGraph& graph = *test::defaultRunGraph();
  const anim::MotionPair pair =
      anim::makeMotionPair(test::defaultClips().slow, test::defaultClips().fast);
  // Bucket 0 plays the slow clip alone, frame for frame (23 frames either way).
  REQUIRE(runCycleFrames(pair, 0.0f, graph.frameTime) == uint32_t(pair.slow.frameCount));
  std::vector<anim::PoseJoint> pose(graph.jointCount);
  for (uint32_t f = 0; f < uint32_t(pair.slow.frameCount); ++f) {
    const NodeJoint* node = graph.pose(f);
    CHECK(node[0].rotation == pair.slow.rotation(int(f), 0));  // root rotation of texture row f
    CHECK(node[0].position.y == pair.slow.offset(int(f), 0).y);
    CHECK(node[0].position.x == 0.0f);
  }
  // The fastest bucket at phase f / F matches poseCharacterSpace exactly.
  const uint32_t last = test::cycleStart(graph, 20);
  const uint32_t frames = runCycleFrames(pair, 1.0f, graph.frameTime);
  for (uint32_t f = 0; f < frames; ++f) {
    anim::poseCharacterSpace(pair, float(f) / float(frames) + 1e-6f, 1.0f, pose);
    for (uint32_t j = 0; j < graph.jointCount; ++j)
      CHECK(graph.pose(last + f)[j].position == pose[j].position);
  }
}

TEST_CASE("buildRunGraph rejects a skeleton that does not fit and a bad bucket width") {
  const anim::MotionPair pair =
      anim::makeMotionPair(test::defaultClips().slow, test::defaultClips().fast);
  anim::Skeleton small = test::defaultClips().slow.skeleton;
  small.joints.pop_back();
  CHECK_THROWS_AS(buildRunGraph(pair, small, 0.05f), Error);
  CHECK_THROWS_AS(buildRunGraph(test::defaultClips(), 0.0f), Error);
  CHECK(buildRunGraph(test::defaultClips(), 1.0f).nodes.size() ==
        runCycleFrames(pair, 0.0f, pair.slow.frameTime) +
            runCycleFrames(pair, 1.0f, pair.slow.frameTime));
}
