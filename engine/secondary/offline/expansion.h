#pragma once
// One unit of exploration work, independent of the graph so it can run on any thread or MPI
// rank: from a cloth state at a primary node, simulate along one primary edge, then
// breadth-first `depth` more frames (every primary successor), and simulate the successors
// of the last frames once more: those are the new dead ends, to be merged by whoever owns the
// graph. The result is a pure function of the task (the simulator is deterministic).
#include <cstdint>
#include <vector>

#include "secondary/secondary_types.h"

namespace throng::secondary {

constexpr uint32_t kFromTaskStart = 0xFFFFFFFFu;

struct ExpansionTask {
  uint32_t node = 0;          // primary node of `start`
  uint32_t edge = 0;          // primary successor index to simulate first
  uint32_t depth = 0;         // BFS levels after the first frame
  uint32_t maxStates = 1;     // new states at most (BFS order); the rest become dead ends
  bool deadEndFrames = true;  // simulate the successors of the new states' open edges
  ClothState start;
};

struct ExpansionState {
  uint32_t node = 0;
  uint32_t parent = kFromTaskStart;  // index into ExpansionResult::states, or the task's start
  uint32_t parentEdge = 0;
  ClothState cloth;
};

// The cloth that simulating states[state] along primary successor `edge` gives (to merge).
struct ExpansionDeadEnd {
  uint32_t state = 0;
  uint32_t edge = 0;
  ClothState cloth;
};

struct ExpansionResult {
  std::vector<ExpansionState> states;  // states[0] comes from the task's start along task.edge
  std::vector<ExpansionDeadEnd> deadEnds;
  uint64_t simulatedSteps() const { return states.size() + deadEnds.size(); }
};

ExpansionResult simulateExpansion(const PrimaryGraph& primary, const StepFunction& step,
                                  const ExpansionTask& task);

// Message encoding for the distributed exploration (binary_io chunks, checksummed).
std::vector<uint8_t> encodeTask(const ExpansionTask& task);
ExpansionTask decodeTask(std::vector<uint8_t> bytes);
std::vector<uint8_t> encodeResult(const ExpansionResult& result);
ExpansionResult decodeResult(std::vector<uint8_t> bytes);

}  // namespace throng::secondary
