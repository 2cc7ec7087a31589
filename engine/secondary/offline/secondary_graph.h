#pragma once
// The secondary motion graph of Kim et al. 2013: cloth states tied to primary nodes, and for
// every state one edge per primary successor of its node. An edge is simulated (the target
// is the cloth the simulator produced along that primary edge), a merge (the simulated cloth
// was replaced by the most similar state at the same primary node; its error is kept), or a
// dead end (not simulated yet: only while the graph is being built).
//
// Every merge edge is in the merge queue, ordered by error (largest first; ties by state then
// edge), so the queue is a function of the edges and the graph is the whole exploration state.
#include <cstdint>
#include <set>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "secondary/secondary_types.h"

namespace throng::secondary {

constexpr uint32_t kNoState = 0xFFFFFFFFu;

struct SecondaryEdge {
  uint32_t target = kNoState;  // kNoState: dead end
  uint32_t isMerge = 0;
  float error = 0.0f;  // merge error in metres (0 for simulated edges)
};

struct MergeKey {
  uint32_t state = 0;
  uint32_t edge = 0;
  float error = 0.0f;
};
struct MergeOrder {
  bool operator()(const MergeKey& a, const MergeKey& b) const {
    if (a.error != b.error) return a.error > b.error;
    if (a.state != b.state) return a.state < b.state;
    return a.edge < b.edge;
  }
};
using MergeQueue = std::set<MergeKey, MergeOrder>;

// One point of the paper's Fig. 7: the largest merge error once `expansions` were done.
struct ErrorSample {
  uint64_t expansions = 0;
  uint64_t states = 0;          // cloth frames in the graph
  uint64_t simulatedSteps = 0;  // simulator calls the graph cost so far
  float maxMergeError = 0.0f;
  uint32_t reserved = 0;
};
static_assert(sizeof(ErrorSample) == 32);

// A read-only view of one cloth frame (vertexCount positions and velocities).
struct FrameView {
  std::span<const glm::vec3> positions;
  std::span<const glm::vec3> velocities;
};
inline FrameView view(const ClothState& s) {
  return {s.positions, s.velocities};
}

struct SecondaryGraph {
  uint32_t vertexCount = 0;
  std::vector<uint32_t> stateNode;
  std::vector<uint32_t> firstEdge{0};  // states + 1
  std::vector<SecondaryEdge> edges;
  std::vector<glm::vec3> positions;                 // states × vertexCount
  std::vector<glm::vec3> velocities;                // states × vertexCount
  std::vector<std::vector<uint32_t>> statesAtNode;  // per primary node, ascending
  MergeQueue queue;
  std::vector<ErrorSample> history;
  uint64_t expansions = 0;
  uint64_t simulatedSteps = 0;

  uint32_t stateCount() const { return uint32_t(stateNode.size()); }
  uint32_t edgeCount(uint32_t state) const { return firstEdge[state + 1] - firstEdge[state]; }
  const SecondaryEdge& edge(uint32_t state, uint32_t k) const {
    return edges[firstEdge[state] + k];
  }
  FrameView frame(uint32_t state) const {
    const size_t at = size_t(state) * vertexCount;
    return {std::span(positions).subspan(at, vertexCount),
            std::span(velocities).subspan(at, vertexCount)};
  }
};

SecondaryGraph makeSecondaryGraph(const PrimaryGraph& primary, uint32_t vertexCount);
// Appends a state at `node` with all its edges dead ends; returns its index.
uint32_t addState(SecondaryGraph& g, const PrimaryGraph& primary, uint32_t node,
                  const ClothState& cloth);
void setSimulatedEdge(SecondaryGraph& g, const PrimaryGraph& primary, uint32_t state, uint32_t k,
                      uint32_t target);
// Turns the dead end (state, k) into a merge into `target` (which must sit at the successor
// node) and queues it.
void mergeEdge(SecondaryGraph& g, const PrimaryGraph& primary, uint32_t state, uint32_t k,
               uint32_t target, float error);
// Turns the merge (state, k) back into a dead end and removes it from the queue.
void undoMerge(SecondaryGraph& g, uint32_t state, uint32_t k);

ClothState clothState(const SecondaryGraph& g, uint32_t state);
uint64_t countDeadEnds(const SecondaryGraph& g);
uint64_t countMerges(const SecondaryGraph& g);
float maxMergeError(const SecondaryGraph& g);
// Rebuilds statesAtNode and the queue from the states and edges (after loading a file).
void rebuildIndexes(SecondaryGraph& g, const PrimaryGraph& primary);
// Throws Error naming the first broken invariant: sizes, edge targets at the primary
// successor's node, queue = merge edges, and (unless allowed) no dead end.
void validateGraph(const SecondaryGraph& g, const PrimaryGraph& primary,
                   bool allowDeadEnds = false);

PlaybackGraph playbackGraph(const SecondaryGraph& g);

}  // namespace throng::secondary
