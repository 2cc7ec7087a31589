#pragma once
// The toy garment on its toy run graph, and exact graph comparison, for the exploration suites.
#include <cstring>
#include <memory>

#include <doctest/doctest.h>

#include "secondary/offline/explore.h"
#include "secondary/offline/garment.h"

namespace throng::secondary::fixtures {

inline Garment toyGarment(uint64_t seed = 1) {
  nlohmann::json config = defaultGarmentConfig("toy");
  config["seed"] = seed;
  return buildGarment(config);
}

inline MergeMetric toyMetric(const Garment& g) {
  return {0.1f, g.term};
}

inline SecondaryGraph initializeToy(const Garment& g, unsigned threads = 1) {
  ThreadedRunner runner(*g.primary, g.step, threads);
  return initializeGraph(*g.primary, runner, toyMetric(g), initialNode(g), initialClothState(g));
}

template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

inline bool sameEdges(const SecondaryGraph& a, const SecondaryGraph& b) {
  if (a.edges.size() != b.edges.size()) return false;
  for (size_t i = 0; i < a.edges.size(); ++i)
    if (a.edges[i].target != b.edges[i].target || a.edges[i].isMerge != b.edges[i].isMerge ||
        std::memcmp(&a.edges[i].error, &b.edges[i].error, sizeof(float)) != 0)
      return false;
  return true;
}

// Every field bit for bit (frames, errors, history, counters).
inline void requireSameGraph(const SecondaryGraph& a, const SecondaryGraph& b) {
  REQUIRE(a.stateCount() == b.stateCount());
  CHECK(a.vertexCount == b.vertexCount);
  CHECK(a.stateNode == b.stateNode);
  CHECK(a.firstEdge == b.firstEdge);
  CHECK(sameEdges(a, b));
  CHECK(sameBits(a.positions, b.positions));
  CHECK(sameBits(a.velocities, b.velocities));
  CHECK(sameBits(a.history, b.history));
  CHECK(a.expansions == b.expansions);
  CHECK(a.simulatedSteps == b.simulatedSteps);
  CHECK(a.queue.size() == b.queue.size());
}

}  // namespace throng::secondary::fixtures
