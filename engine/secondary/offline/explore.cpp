#include "secondary/offline/explore.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <optional>

#include "core/error.h"
#include "secondary/offline/worker_pool.h"

namespace throng::secondary {

ThreadedRunner::ThreadedRunner(const PrimaryGraph& primary, StepFunction step, unsigned threads)
    : primary_(primary), step_(std::move(step)), pool_(std::make_unique<WorkerPool>(threads)) {}

ThreadedRunner::~ThreadedRunner() = default;

unsigned ThreadedRunner::workers() const {
  return pool_->threads();
}

std::vector<ExpansionResult> ThreadedRunner::run(const std::vector<ExpansionTask>& tasks) {
  std::vector<ExpansionResult> results(tasks.size());
  pool_->run(tasks.size(),
             [&](size_t i) { results[i] = simulateExpansion(primary_, step_, tasks[i]); });
  return results;
}

const char* exploreStopName(ExploreStop stop) {
  switch (stop) {
    case ExploreStop::Expansions:
      return "expansion budget reached";
    case ExploreStop::Seconds:
      return "time budget reached";
    case ExploreStop::TargetError:
      return "target error reached";
    case ExploreStop::QueueEmpty:
      return "no merge left";
    case ExploreStop::Interrupted:
      return "interrupted";
  }
  return "?";
}

namespace {
ErrorSample sample(const SecondaryGraph& g) {
  return {g.expansions, g.stateCount(), g.simulatedSteps, maxMergeError(g), 0};
}

using EdgeKey = std::pair<uint32_t, uint32_t>;
EdgeKey edgeKey(const MergeKey& m) {
  return {m.state, m.edge};
}
}  // namespace

SecondaryGraph initializeGraph(const PrimaryGraph& primary, ExpansionRunner& runner,
                               const MergeMetric& metric, uint32_t initialNode,
                               const ClothState& initial) {
  if (initialNode >= primary.nodes.size())
    fail("initial primary node ", initialNode, " out of range (the primary graph has ",
         primary.nodes.size(), " nodes)");
  SecondaryGraph g = makeSecondaryGraph(primary, uint32_t(initial.positions.size()));
  std::vector<uint32_t> frontier{addState(g, primary, initialNode, initial)};
  while (!frontier.empty()) {
    std::vector<ExpansionTask> tasks;
    std::vector<EdgeKey> from;
    for (uint32_t s : frontier)
      for (uint32_t k = 0; k < g.edgeCount(s); ++k) {
        tasks.push_back({g.stateNode[s], k, 0, 1, false, clothState(g, s)});
        from.push_back({s, k});
      }
    const std::vector<ExpansionResult> results = runner.run(tasks);
    THRONG_CHECK(results.size() == tasks.size(), "runner returned ", results.size(),
                 " results for ", tasks.size(), " tasks");
    std::vector<uint32_t> next;
    for (size_t i = 0; i < results.size(); ++i) {
      THRONG_CHECK(results[i].states.size() == 1 && results[i].deadEnds.empty(),
                   "initialisation step result");
      const ExpansionState& st = results[i].states[0];
      const auto [s, k] = from[i];
      THRONG_CHECK(st.node == primary.successors[g.stateNode[s]][k],
                   "initialisation step reached the wrong node");
      g.simulatedSteps += 1;
      if (g.statesAtNode[st.node].empty()) {
        const uint32_t t = addState(g, primary, st.node, st.cloth);
        setSimulatedEdge(g, primary, s, k, t);
        next.push_back(t);
      } else {
        const MergeTarget m = findMergeTarget(g, metric, st.node, view(st.cloth));
        mergeEdge(g, primary, s, k, m.state, m.error);
      }
    }
    frontier = std::move(next);
  }
  g.history.push_back(sample(g));
  return g;
}

void applyExpansion(SecondaryGraph& g, const PrimaryGraph& primary, const MergeMetric& metric,
                    const MergeKey& undone, const ExpansionResult& result) {
  THRONG_CHECK(!result.states.empty() && result.states[0].parent == kFromTaskStart,
               "expansion result without its first state");
  const uint32_t base = g.stateCount();
  for (const ExpansionState& st : result.states) addState(g, primary, st.node, st.cloth);
  for (size_t i = 0; i < result.states.size(); ++i) {
    const ExpansionState& st = result.states[i];
    if (i == 0) {
      setSimulatedEdge(g, primary, undone.state, undone.edge, base);
    } else {
      THRONG_CHECK(st.parent < i, "expansion state ", i, " has parent ", st.parent);
      setSimulatedEdge(g, primary, base + st.parent, st.parentEdge, base + uint32_t(i));
    }
  }
  for (const ExpansionDeadEnd& d : result.deadEnds) {
    const uint32_t from = base + d.state;
    THRONG_CHECK(d.state < result.states.size() && d.edge < g.edgeCount(from),
                 "expansion dead end (", d.state, ", ", d.edge, ")");
    const uint32_t node = primary.successors[g.stateNode[from]][d.edge];
    const MergeTarget m = findMergeTarget(g, metric, node, view(d.cloth));
    mergeEdge(g, primary, from, d.edge, m.state, m.error);
  }
  g.simulatedSteps += result.simulatedSteps();
}

ExpansionTask expansionTask(const SecondaryGraph& g, const ExpandOptions& options,
                            const MergeKey& merge) {
  return {g.stateNode[merge.state],        merge.edge, options.depth,
          std::max(1u, options.maxStates), true,       clothState(g, merge.state)};
}

ExploreStop exploreGraph(SecondaryGraph& g, const PrimaryGraph& primary, ExpansionRunner& runner,
                         const MergeMetric& metric, const ExpandOptions& options,
                         const ExploreBudget& budget, const ExploreHooks& hooks) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  Clock::time_point lastCheckpoint = start;
  const size_t lookahead =
      options.lookahead ? options.lookahead : 2 * std::max(1u, runner.workers());
  std::map<EdgeKey, ExpansionResult> memo;

  auto stopReason = [&]() -> std::optional<ExploreStop> {
    if (g.queue.empty()) return ExploreStop::QueueEmpty;
    if (hooks.interrupted && hooks.interrupted()) return ExploreStop::Interrupted;
    if (budget.targetError > 0.0f && maxMergeError(g) <= budget.targetError)
      return ExploreStop::TargetError;
    if (budget.expansions && g.expansions >= budget.expansions) return ExploreStop::Expansions;
    if (budget.seconds > 0.0 &&
        std::chrono::duration<double>(Clock::now() - start).count() >= budget.seconds)
      return ExploreStop::Seconds;
    return std::nullopt;
  };

  for (;;) {
    if (std::optional<ExploreStop> stop = stopReason()) return *stop;
    const MergeKey top = *g.queue.begin();
    auto found = memo.find(edgeKey(top));
    if (found == memo.end()) {
      // Speculate on the worst merges not simulated yet (top included: it is the first).
      const uint64_t left = budget.expansions ? budget.expansions - g.expansions
                                              : std::numeric_limits<uint64_t>::max();
      const size_t want = size_t(std::min<uint64_t>(lookahead, left));
      std::vector<ExpansionTask> tasks;
      std::vector<EdgeKey> keys;
      for (const MergeKey& m : g.queue) {
        if (tasks.size() >= want) break;
        if (memo.count(edgeKey(m))) continue;
        tasks.push_back(expansionTask(g, options, m));
        keys.push_back(edgeKey(m));
      }
      std::vector<ExpansionResult> results = runner.run(tasks);
      THRONG_CHECK(results.size() == tasks.size(), "runner returned ", results.size(),
                   " results for ", tasks.size(), " tasks");
      for (size_t i = 0; i < tasks.size(); ++i) memo.emplace(keys[i], std::move(results[i]));
      found = memo.find(edgeKey(top));
    }
    const ExpansionResult result = std::move(found->second);
    memo.erase(found);
    undoMerge(g, top.state, top.edge);
    applyExpansion(g, primary, metric, top, result);
    ++g.expansions;
    g.history.push_back(sample(g));
    if (hooks.progress) hooks.progress(g);
    const bool byCount = hooks.checkpointEvery && g.expansions % hooks.checkpointEvery == 0;
    const bool byTime = hooks.checkpointSeconds > 0.0 &&
                        std::chrono::duration<double>(Clock::now() - lastCheckpoint).count() >=
                            hooks.checkpointSeconds;
    if (hooks.checkpoint && (byCount || byTime)) {
      hooks.checkpoint(g);
      lastCheckpoint = Clock::now();
    }
  }
}

}  // namespace throng::secondary
