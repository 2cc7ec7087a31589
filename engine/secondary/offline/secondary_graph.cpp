#include "secondary/offline/secondary_graph.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace throng::secondary {
namespace {
SecondaryEdge& edgeAt(SecondaryGraph& g, uint32_t state, uint32_t k) {
  THRONG_CHECK(state < g.stateCount() && k < g.edgeCount(state), "edge (", state, ", ", k,
               ") out of range");
  return g.edges[g.firstEdge[state] + k];
}

uint32_t successorNode(const SecondaryGraph& g, const PrimaryGraph& primary, uint32_t state,
                       uint32_t k) {
  return primary.successors[g.stateNode[state]][k];
}
}  // namespace

SecondaryGraph makeSecondaryGraph(const PrimaryGraph& primary, uint32_t vertexCount) {
  SecondaryGraph g;
  g.vertexCount = vertexCount;
  g.statesAtNode.resize(primary.nodes.size());
  return g;
}

uint32_t addState(SecondaryGraph& g, const PrimaryGraph& primary, uint32_t node,
                  const ClothState& cloth) {
  THRONG_CHECK(node < primary.nodes.size(), "primary node ", node, " of ", primary.nodes.size());
  THRONG_CHECK(cloth.positions.size() == g.vertexCount && cloth.velocities.size() == g.vertexCount,
               "cloth state has ", cloth.positions.size(), " positions and ",
               cloth.velocities.size(), " velocities, the graph ", g.vertexCount, " vertices");
  const uint32_t id = g.stateCount();
  g.stateNode.push_back(node);
  g.edges.resize(g.edges.size() + primary.successors[node].size());
  g.firstEdge.push_back(uint32_t(g.edges.size()));
  g.positions.insert(g.positions.end(), cloth.positions.begin(), cloth.positions.end());
  g.velocities.insert(g.velocities.end(), cloth.velocities.begin(), cloth.velocities.end());
  if (g.statesAtNode.size() < primary.nodes.size()) g.statesAtNode.resize(primary.nodes.size());
  g.statesAtNode[node].push_back(id);
  return id;
}

void setSimulatedEdge(SecondaryGraph& g, const PrimaryGraph& primary, uint32_t state, uint32_t k,
                      uint32_t target) {
  SecondaryEdge& e = edgeAt(g, state, k);
  THRONG_CHECK(e.target == kNoState, "edge (", state, ", ", k, ") is not a dead end");
  THRONG_CHECK(
      target < g.stateCount() && g.stateNode[target] == successorNode(g, primary, state, k),
      "simulated edge (", state, ", ", k, ") must reach the successor node");
  e = {target, 0, 0.0f};
}

void mergeEdge(SecondaryGraph& g, const PrimaryGraph& primary, uint32_t state, uint32_t k,
               uint32_t target, float error) {
  SecondaryEdge& e = edgeAt(g, state, k);
  THRONG_CHECK(e.target == kNoState, "edge (", state, ", ", k, ") is not a dead end");
  THRONG_CHECK(
      target < g.stateCount() && g.stateNode[target] == successorNode(g, primary, state, k),
      "merge (", state, ", ", k, ") → ", target, " must join states of the same primary node");
  if (!std::isfinite(error) || error < 0.0f)
    fail("merge error ", error, " at state ", state, " (primary node ", g.stateNode[state],
         "): the simulator produced a non-finite cloth state");
  e = {target, 1, error};
  g.queue.insert({state, k, error});
}

void undoMerge(SecondaryGraph& g, uint32_t state, uint32_t k) {
  SecondaryEdge& e = edgeAt(g, state, k);
  THRONG_CHECK(e.isMerge, "edge (", state, ", ", k, ") is not a merge");
  const size_t erased = g.queue.erase({state, k, e.error});
  THRONG_CHECK(erased == 1, "merge (", state, ", ", k, ") missing from the queue");
  e = {};
}

ClothState clothState(const SecondaryGraph& g, uint32_t state) {
  const FrameView f = g.frame(state);
  return {{f.positions.begin(), f.positions.end()}, {f.velocities.begin(), f.velocities.end()}};
}

uint64_t countDeadEnds(const SecondaryGraph& g) {
  return uint64_t(std::count_if(g.edges.begin(), g.edges.end(),
                                [](const SecondaryEdge& e) { return e.target == kNoState; }));
}

uint64_t countMerges(const SecondaryGraph& g) {
  return uint64_t(std::count_if(g.edges.begin(), g.edges.end(),
                                [](const SecondaryEdge& e) { return e.isMerge != 0; }));
}

float maxMergeError(const SecondaryGraph& g) {
  return g.queue.empty() ? 0.0f : g.queue.begin()->error;
}

void rebuildIndexes(SecondaryGraph& g, const PrimaryGraph& primary) {
  g.statesAtNode.assign(primary.nodes.size(), {});
  g.queue.clear();
  for (uint32_t s = 0; s < g.stateCount(); ++s) {
    THRONG_CHECK(g.stateNode[s] < primary.nodes.size(), "state ", s, " at primary node ",
                 g.stateNode[s]);
    g.statesAtNode[g.stateNode[s]].push_back(s);
    for (uint32_t k = 0; k < g.edgeCount(s); ++k)
      if (g.edge(s, k).isMerge) g.queue.insert({s, k, g.edge(s, k).error});
  }
}

void validateGraph(const SecondaryGraph& g, const PrimaryGraph& primary, bool allowDeadEnds) {
  const uint32_t n = g.stateCount();
  if (g.firstEdge.size() != size_t(n) + 1 || g.firstEdge[0] != 0 ||
      g.firstEdge.back() != g.edges.size())
    fail("secondary graph: edge offsets do not match ", n, " states and ", g.edges.size(),
         " edges");
  if (g.positions.size() != size_t(n) * g.vertexCount ||
      g.velocities.size() != size_t(n) * g.vertexCount)
    fail("secondary graph: ", g.positions.size(), " positions for ", n, " states of ",
         g.vertexCount, " vertices");
  size_t merges = 0;
  for (uint32_t s = 0; s < n; ++s) {
    const uint32_t node = g.stateNode[s];
    if (node >= primary.nodes.size()) fail("state ", s, ": primary node ", node, " out of range");
    if (g.edgeCount(s) != primary.successors[node].size())
      fail("state ", s, ": ", g.edgeCount(s), " edges, its primary node ", node, " has ",
           primary.successors[node].size(), " successors");
    for (uint32_t k = 0; k < g.edgeCount(s); ++k) {
      const SecondaryEdge& e = g.edge(s, k);
      if (e.target == kNoState) {
        if (!allowDeadEnds) fail("state ", s, " edge ", k, ": dead end");
        continue;
      }
      if (e.target >= n) fail("state ", s, " edge ", k, ": target ", e.target, " out of range");
      if (g.stateNode[e.target] != primary.successors[node][k])
        fail("state ", s, " edge ", k, ": target ", e.target, " sits at primary node ",
             g.stateNode[e.target], ", the primary successor is ", primary.successors[node][k]);
      if (e.isMerge) {
        ++merges;
        if (!g.queue.count({s, k, e.error}))
          fail("state ", s, " edge ", k, ": merge missing from the queue");
      } else if (e.error != 0.0f) {
        fail("state ", s, " edge ", k, ": simulated edge with a merge error");
      }
    }
  }
  if (g.queue.size() != merges)
    fail("merge queue holds ", g.queue.size(), " entries for ", merges, " merge edges");
}

PlaybackGraph playbackGraph(const SecondaryGraph& g) {
  PlaybackGraph p;
  p.stateNode = g.stateNode;
  p.firstEdge = g.firstEdge;
  p.edgeTarget.reserve(g.edges.size());
  p.edgeIsMerge.reserve(g.edges.size());
  for (const SecondaryEdge& e : g.edges) {
    if (e.target == kNoState) fail("playback graph: the secondary graph still has dead ends");
    p.edgeTarget.push_back(e.target);
    p.edgeIsMerge.push_back(uint8_t(e.isMerge ? 1 : 0));
  }
  return p;
}

}  // namespace throng::secondary
