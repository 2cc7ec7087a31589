#pragma once
// Building and expanding the secondary graph (Kim et al. 2013, §4): breadth-first
// initialisation over every primary edge, then ExpandGraph until a budget: pop the
// largest-error merge, undo it, simulate from it, merge the new dead ends.
//
// Determinism: the result is that of the sequential algorithm (one expansion at a time, always
// the current worst merge), whatever the number of threads or MPI ranks. Parallelism is
// speculative: the runner simulates the k worst merges at once and their results wait in a
// memo until each becomes the worst; an expansion's simulation depends only on its start state
// and primary edge, so a waiting result never goes stale.
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "secondary/offline/expansion.h"
#include "secondary/offline/merge_metric.h"
#include "secondary/offline/secondary_graph.h"

namespace throng::secondary {

// Runs a batch of expansion tasks somewhere (threads, MPI ranks); results in task order.
class ExpansionRunner {
 public:
  virtual ~ExpansionRunner() = default;
  virtual std::vector<ExpansionResult> run(const std::vector<ExpansionTask>& tasks) = 0;
  virtual unsigned workers() const = 0;
};

class WorkerPool;
class ThreadedRunner final : public ExpansionRunner {
 public:
  ThreadedRunner(const PrimaryGraph& primary, StepFunction step, unsigned threads);
  ~ThreadedRunner() override;
  std::vector<ExpansionResult> run(const std::vector<ExpansionTask>& tasks) override;
  unsigned workers() const override;

 private:
  const PrimaryGraph& primary_;
  StepFunction step_;
  std::unique_ptr<WorkerPool> pool_;
};

struct ExpandOptions {
  uint32_t depth = 3;       // BFS levels simulated after the undone merge's frame
  uint32_t maxStates = 64;  // new states per expansion at most
  uint32_t lookahead = 0;   // merges simulated ahead per batch; 0: 2 × runner workers
};

struct ExploreBudget {
  uint64_t expansions = 0;   // total expansions of the graph (counting earlier runs); 0: none
  double seconds = 0.0;      // wall time of this call; 0: none
  float targetError = 0.0f;  // stop once the largest merge error is at most this; 0: none
};

enum class ExploreStop { Expansions, Seconds, TargetError, QueueEmpty, Interrupted };
const char* exploreStopName(ExploreStop stop);

struct ExploreHooks {
  uint64_t checkpointEvery = 0;    // expansions; 0: never
  double checkpointSeconds = 0.0;  // wall time since the last checkpoint; 0: never
  std::function<void(const SecondaryGraph&)> checkpoint;
  std::function<void(const SecondaryGraph&)> progress;  // after every expansion
  std::function<bool()> interrupted;                    // polled between expansions
};

// A graph with one state (initial) at `initialNode`, then every primary edge reachable from it
// simulated once: the first frame to reach a primary node becomes its state, the others are
// merged into it. Leaves no dead end.
SecondaryGraph initializeGraph(const PrimaryGraph& primary, ExpansionRunner& runner,
                               const MergeMetric& metric, uint32_t initialNode,
                               const ClothState& initial);

// Adds the result of expanding `undone` (a merge already removed from the graph, now a dead
// end) and merges its dead ends.
void applyExpansion(SecondaryGraph& g, const PrimaryGraph& primary, const MergeMetric& metric,
                    const MergeKey& undone, const ExpansionResult& result);

ExpansionTask expansionTask(const SecondaryGraph& g, const ExpandOptions& options,
                            const MergeKey& merge);

ExploreStop exploreGraph(SecondaryGraph& g, const PrimaryGraph& primary, ExpansionRunner& runner,
                         const MergeMetric& metric, const ExpandOptions& options,
                         const ExploreBudget& budget, const ExploreHooks& hooks = {});

}  // namespace throng::secondary
