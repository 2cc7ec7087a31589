// throng cloth explore|info: the secondary motion graph of a garment explored along the crowd's
// primary motion graph (Kim et al. 2013), checkpointed to a .tsg file and resumable; info on
// .tsg graphs and .tsc compressed databases. `cloth compress` lives in cmd_cloth_compress.cpp.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_errors.h"
#include "command.h"
#include "core/binary_io.h"
#include "core/error.h"
#include "core/file_io.h"
#include "secondary/cloth_database.h"
#include "secondary/offline/blend_motion.h"
#include "secondary/offline/cloth_compress.h"
#include "secondary/offline/explore.h"
#include "secondary/offline/explore_file.h"
#include "secondary/offline/garment.h"
#ifdef THRONG_HAVE_MPI
#include "secondary/mpi/explore_mpi.h"
#endif

namespace throng::tools {
namespace {
namespace sec = throng::secondary;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

struct ExploreArgs {
  std::optional<std::string> garment;
  std::optional<std::string> garmentConfig;
  std::optional<uint64_t> seed;
  std::optional<uint32_t> initialNode;
  std::optional<uint32_t> depth;
  std::optional<uint32_t> maxStates;
  std::optional<float> velocityScale;
  std::string slow, fast;  // the run pair's BVH files (empty: the built-in run)
  uint64_t budgetExpansions = 0;
  double budgetSeconds = 0.0;
  float targetError = 0.0f;
  unsigned threads = 0;
  uint64_t checkpointEvery = 0;
  double checkpointSeconds = 60.0;
  bool resume = false, mpi = false, quiet = false, json = false;
  std::string out;
};

// Ctrl-C ends a threaded exploration after the current expansion, with a final checkpoint.
// (Under mpirun every rank gets the signal, so the MPI run keeps the default: the last
// checkpoint on disk is the result.)
std::atomic<bool> gInterrupted{false};
void onInterrupt(int) {
  gInterrupted = true;
}

double secondsSince(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// One stderr line rewritten in place (only on a terminal, at most 5 times a second).
class ProgressBar {
 public:
  ProgressBar(bool enabled, const sec::ExploreBudget& budget, uint64_t startExpansions,
              uint64_t startStates)
      : enabled_(enabled && ::isatty(2)),
        budget_(budget),
        startExpansions_(startExpansions),
        startStates_(startStates) {}

  void update(const sec::SecondaryGraph& g, bool force = false) {
    if (!enabled_ || (!force && secondsSince(last_) < 0.2)) return;
    last_ = Clock::now();
    const double elapsed = secondsSince(start_);
    double fraction = 0.0;
    if (budget_.expansions)
      fraction =
          double(g.expansions - startExpansions_) / double(budget_.expansions - startExpansions_);
    if (budget_.seconds > 0.0) fraction = std::max(fraction, elapsed / budget_.seconds);
    fraction = std::clamp(fraction, 0.0, 1.0);
    const int width = 24, filled = int(fraction * width + 0.5);
    std::fprintf(
        stderr,
        "\r[%s%s] %3d%%  %llu expansions  %u frames  max merge error %.1f mm  %.1f frames/s   ",
        std::string(size_t(filled), '#').c_str(), std::string(size_t(width - filled), '.').c_str(),
        int(fraction * 100.0), (unsigned long long)g.expansions, g.stateCount(),
        1000.0 * sec::maxMergeError(g),
        double(g.stateCount() - startStates_) / std::max(elapsed, 1e-9));
    std::fflush(stderr);
  }
  void finish(const sec::SecondaryGraph& g) {
    if (!enabled_) return;
    update(g, true);
    std::fputc('\n', stderr);
  }

 private:
  bool enabled_;
  sec::ExploreBudget budget_;
  uint64_t startExpansions_, startStates_;
  Clock::time_point start_ = Clock::now(), last_ = Clock::time_point{};
};

// The velocity term's default time scale is one frame: a velocity difference counts as the
// drift it makes in one frame. (Longer scales let the simulator's velocity spikes near the
// pins, several m/s at single vertices, dominate the merge error of the cape.)
json exploreOptionsJson(const ExploreArgs& a, float frameTime) {
  return {{"depth", a.depth.value_or(3)},
          {"max_states", a.maxStates.value_or(64)},
          {"velocity_scale", a.velocityScale.value_or(frameTime)}};
}

json newGarmentConfig(const ExploreArgs& a) {
  json garment = {{"name", a.garment.value_or("cape")}};
  if (a.garmentConfig) {
    json overrides;
    try {
      overrides = json::parse(*a.garmentConfig);
    } catch (const json::exception& e) {
      fail("--garment-config: not valid JSON (", e.what(), ")");
    }
    if (!overrides.is_object()) fail("--garment-config: expected a JSON object");
    if (overrides.contains("name") && overrides["name"] != garment["name"])
      fail("--garment-config: name ", overrides["name"].dump(), " contradicts --garment ",
           garment["name"].dump());
    garment.update(overrides);
  }
  if (a.seed) garment["seed"] = *a.seed;
  if (a.initialNode) garment["initial_node"] = *a.initialNode;
  if (!a.slow.empty()) {
    if (garment["name"] != "cape") fail("--slow and --fast: only the cape runs on a clip pair");
    garment["slow"] = a.slow;
    garment["fast"] = a.fast;
  }
  return sec::completeGarmentConfig(garment);
}

// A resumed run keeps the file's settings; options that would change them are refused.
void checkResumeArgs(const ExploreArgs& a, const json& config) {
  const json& g = config.at("garment");
  auto differs = [&](const char* option, const json& given, const json& stored) {
    if (given != stored)
      fail(option, " ", given.dump(), " differs from the resumed file's ", stored.dump(),
           ": a resumed exploration keeps the settings it was started with");
  };
  if (a.garment) differs("--garment", *a.garment, g.at("name"));
  if (a.seed) differs("--seed", *a.seed, g.at("seed"));
  if (a.initialNode) differs("--initial-node", *a.initialNode, g.at("initial_node"));
  if (a.garmentConfig) fail("--garment-config cannot change a resumed exploration");
  if (!a.slow.empty())
    fail(
        "--slow and --fast cannot change a resumed exploration (it keeps the clips it was "
        "started with: ",
        g.value("slow", "").empty() ? std::string("the built-in run")
                                    : g.value("slow", "") + " + " + g.value("fast", ""),
        ")");
  const json& e = config.at("explore");
  if (a.depth) differs("--depth", *a.depth, e.at("depth"));
  if (a.maxStates) differs("--max-states", *a.maxStates, e.at("max_states"));
  if (a.velocityScale) differs("--velocity-scale", *a.velocityScale, e.at("velocity_scale"));
}

sec::ExpandOptions expandOptions(const json& config) {
  sec::ExpandOptions o;
  o.depth = config.at("explore").at("depth");
  o.maxStates = config.at("explore").at("max_states");
  if (o.depth > 1000 || o.maxStates < 1)
    fail("explore options out of range: ", config.at("explore").dump());
  return o;
}

void runExplore(const ExploreArgs& a) {
#ifdef THRONG_HAVE_MPI
  // Every rank runs this command; ranks > 0 only serve expansion tasks to rank 0.
  std::unique_ptr<sec::mpi::MpiSession> session;
  if (a.mpi) {
    session = std::make_unique<sec::mpi::MpiSession>();
    if (session->rank() != 0) return sec::mpi::runWorker(*session);
  }
#else
  if (a.mpi)
    fail("--mpi: this build has no Open MPI support (install libopenmpi-dev and reconfigure)");
#endif
  const std::filesystem::path out = a.out;
  if (a.slow.empty() != a.fast.empty()) fail("--slow and --fast must be given together");
  if (a.threads > 1024) fail("--threads ", a.threads, ": expected 0 (all cores) to 1024");
  // A run killed while it wrote a checkpoint left "<out>.tmp-PID": gone before this one starts.
  for (const std::filesystem::path& stale : prepareOutputFile(out, "--out"))
    if (!a.quiet && !a.json)
      std::fprintf(stderr, "removed %s (left by a run that was killed)\n", stale.c_str());

  sec::ExploreBudget budget{a.budgetExpansions, a.budgetSeconds, a.targetError};
  if (!budget.expansions && budget.seconds <= 0.0 && budget.targetError <= 0.0f)
    budget.expansions = 100;

  const Clock::time_point start = Clock::now();
  json config;
  sec::Garment garment;
  sec::SecondaryGraph graph;
  bool initialized = false;
  if (a.resume) {
    if (!std::filesystem::exists(out))
      fail(out.string(), ": --resume needs an existing graph to continue");
    sec::ExploreFile file = sec::loadExploreFile(out);
    config = std::move(file.config);
    checkResumeArgs(a, config);
    garment =
        sec::restoreGarment(config.at("garment"), std::move(file.primary), std::move(file.mesh));
    garment.clips = std::move(file.clips);
    graph = std::move(file.graph);
    if (sec::countDeadEnds(graph))
      fail(out.string(), ": the graph has dead ends, it was not written by a finished step");
  } else {
    garment = sec::buildGarment(newGarmentConfig(a));
    config = {{"garment", garment.config},
              {"explore", exploreOptionsJson(a, garment.primary->frameTime)}};
  }
  const sec::MergeMetric metric{config.at("explore").at("velocity_scale").get<float>(),
                                garment.term};
  const sec::ExpandOptions options = expandOptions(config);

  std::unique_ptr<sec::ExpansionRunner> runner;
#ifdef THRONG_HAVE_MPI
  if (a.mpi) runner = std::make_unique<sec::mpi::MpiRunner>(*session, garment);
#endif
  if (!runner)
    runner = std::make_unique<sec::ThreadedRunner>(*garment.primary, garment.step, a.threads);

  auto save = [&](const sec::SecondaryGraph& g) {
    sec::saveExploreFile(out, config, *garment.primary, *garment.mesh, g, garment.clips);
  };
  if (!a.resume) {
    if (!a.quiet && !a.json)
      std::fprintf(stderr, "initialising: %zu primary nodes, %u cloth vertices…\n",
                   garment.primary->nodes.size(), garment.mesh->vertexCount());
    graph = sec::initializeGraph(*garment.primary, *runner, metric, sec::initialNode(garment),
                                 sec::initialClothState(garment));
    save(graph);
    initialized = true;
  }
  const uint64_t startExpansions = graph.expansions,
                 startStates = initialized ? 0 : graph.stateCount();
  const uint64_t startSteps = initialized ? 0 : graph.simulatedSteps;
  ProgressBar bar(!a.quiet && !a.json, budget, startExpansions, startStates);
  sec::ExploreHooks hooks;
  hooks.checkpointEvery = a.checkpointEvery;
  hooks.checkpointSeconds = a.checkpointSeconds;
  hooks.checkpoint = save;
  hooks.progress = [&](const sec::SecondaryGraph& g) { bar.update(g); };
  if (!a.mpi) {
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
    hooks.interrupted = [] { return gInterrupted.load(); };
  }
  const sec::ExploreStop stop =
      sec::exploreGraph(graph, *garment.primary, *runner, metric, options, budget, hooks);
  save(graph);
  bar.finish(graph);
  const double seconds = secondsSince(start);

  json r;
  r["file"] = out.string();
  r["garment"] = config["garment"]["name"];
  r["clips"] = garment.clips.name;
  r["states"] = graph.stateCount();
  r["frames"] = graph.stateCount();
  r["vertices"] = graph.vertexCount;
  r["primary_nodes"] = garment.primary->nodes.size();
  r["dead_ends"] = sec::countDeadEnds(graph);
  r["merge_edges"] = graph.queue.size();
  r["expansions"] = graph.expansions;
  r["expansions_this_run"] = graph.expansions - startExpansions;
  r["max_merge_error_m"] = sec::maxMergeError(graph);
  r["initial_max_merge_error_m"] =
      graph.history.empty() ? 0.0f : graph.history.front().maxMergeError;
  r["stop"] = sec::exploreStopName(stop);
  r["seconds"] = seconds;
  r["frames_per_second"] = double(graph.stateCount() - startStates) / std::max(seconds, 1e-9);
  r["steps_per_second"] = double(graph.simulatedSteps - startSteps) / std::max(seconds, 1e-9);
  r["mode"] = a.mpi ? "mpi" : "threads";
  r["workers"] = runner->workers();
  r["bytes"] = std::filesystem::file_size(out);
  sec::writeFloatsShort(r);
  if (a.json) {
    r["schema"] = "throng.cloth_explore";
    r["version"] = 1;
    std::cout << r.dump(2) << '\n';
    return;
  }
  std::printf(
      "%s: %u cloth frames at %zu primary nodes, %llu merge edges, %llu dead ends; %llu expansions "
      "(%s)\n",
      out.string().c_str(), graph.stateCount(), garment.primary->nodes.size(),
      (unsigned long long)graph.queue.size(), (unsigned long long)sec::countDeadEnds(graph),
      (unsigned long long)graph.expansions, sec::exploreStopName(stop));
  std::printf("  clips: %s\n", garment.clips.describe().c_str());
  std::printf("  largest merge error %.2f mm (%.2f mm after initialisation)\n",
              1000.0 * sec::maxMergeError(graph),
              1000.0 * r["initial_max_merge_error_m"].get<double>());
  std::printf("  %.1f frames/s explored, %.1f simulator steps/s, %u %s, %.1f s; %.1f MB\n",
              r["frames_per_second"].get<double>(), r["steps_per_second"].get<double>(),
              runner->workers(), a.mpi ? "worker ranks" : "threads", seconds,
              double(r["bytes"].get<uint64_t>()) / 1e6);
}

struct InfoArgs {
  std::string file;
  bool json = false, history = false, blendMotion = false;
};

// How much the shown cape moves in a frame that crosses a merge edge against any other frame.
json blendMotionJson(const std::filesystem::path& path) {
  sec::BlendMotionOptions options;
  options.characters = 64;
  options.steps = 600;
  const sec::BlendMotionReport r =
      readMagic(path) == sec::kTsgMagic
          ? sec::measureBlendMotion(sec::loadExploreFile(path), options)
          : sec::measureBlendMotion(sec::readClothDatabase(path), options);
  return {{"merge_steps", r.mergeSteps.size()},
          {"ordinary_steps", r.ordinarySteps.size()},
          {"p95_move_at_merge_m", r.p95Merge},
          {"p95_move_ordinary_m", r.p95Ordinary},
          {"merge_over_ordinary", r.ratio()}};
}

// One function per file kind, chosen by the magic.
json fileInfo(const std::filesystem::path& path, bool history) {
  const std::string magic = readMagic(path);
  if (magic == sec::kTsgMagic) return sec::exploreFileInfo(path, history);
  if (magic == sec::kClothDatabaseMagic) return sec::clothCompressedInfo(path);
  std::string shown;
  for (char c : magic) shown += (c >= 32 && c < 127) ? c : '?';
  fail(path.string(), ": not a secondary graph (.tsg) or compressed cloth (.tsc) file (magic '",
       shown, "')");
}

void runInfo(const InfoArgs& a) {
  json info = fileInfo(a.file, a.history);
  if (a.blendMotion) {
    const json blend = blendMotionJson(a.file);
    for (auto it = blend.begin(); it != blend.end(); ++it) info["blend_" + it.key()] = *it;
  }
  sec::writeFloatsShort(info);
  if (a.json) {
    info["schema"] = "throng.cloth_info";
    info["version"] = 1;
    std::cout << info.dump(2) << '\n';
    return;
  }
  std::printf("%s\n", a.file.c_str());
  for (auto it = info.begin(); it != info.end(); ++it)
    if (!it->is_structured() && it.key() != "file")
      std::printf("  %-32s %s\n", it.key().c_str(), it->dump().c_str());
}

CLI::App* clothCommand(CLI::App& app) {
  // Shared with tools/cmd_cloth_compress.
  return commandGroup(app, "cloth", "Secondary motion: cloth exploration, compression, info");
}

void addClothExploreCommands(CLI::App& app) {
  CLI::App* cloth = clothCommand(app);

  auto a = std::make_shared<ExploreArgs>();
  CLI::App* explore = cloth->add_subcommand(
      "explore", "Explore a garment's secondary motion graph (Kim et al. 2013) into a .tsg file");
  explore
      ->add_option("--garment", a->garment,
                   "Garment: cape (default) or toy (a tiny pendulum chain, for tests)")
      ->check(CLI::IsMember({"cape", "toy"}));
  explore->add_option(
      "--garment-config", a->garmentConfig,
      "JSON overriding garment settings, e.g. '{\"cape\": {\"columns\": 16, \"rows\": 24}}'");
  explore->add_option(
      "--budget-expansions", a->budgetExpansions,
      "Stop when the graph has had this many expansions in all (counting a resumed file's); "
      "default 100 when no budget is given");
  explore
      ->add_option("--budget-seconds", a->budgetSeconds, "Stop after this many seconds of this run")
      ->check(CLI::Range(0.0, 1e9));
  explore
      ->add_option("--target-error", a->targetError,
                   "Stop once the largest merge error is at most this (metres)")
      ->check(inRange(0, 1000, "metres"));
  explore->add_option("--threads", a->threads,
                      "Simulation threads (0: all cores; ignored with --mpi)");
  explore->add_option("--slow", a->slow,
                      "Slow cycle BVH of the run pair the cape is explored on (with --fast; any "
                      "pair `throng render --slow --fast` accepts; default: the built-in run)");
  explore->add_option("--fast", a->fast, "Fast cycle BVH of the run pair (with --slow)");
  explore->add_option("--seed", a->seed, "Seed of the initial cloth's velocity jitter (default 1)");
  explore->add_option("--initial-node", a->initialNode,
                      "Primary node the exploration starts at (default 0)");
  explore
      ->add_option("--depth", a->depth,
                   "Frames simulated breadth-first after each undone merge (default 3)")
      ->check(CLI::Range(0, 1000));
  explore
      ->add_option("--max-states", a->maxStates,
                   "New cloth states per expansion at most (default 64)")
      ->check(CLI::Range(1, 1000000));
  explore
      ->add_option("--velocity-scale", a->velocityScale,
                   "Seconds that weigh velocity differences in the merge error (default: one "
                   "frame, 1/30)")
      ->check(CLI::Range(0.0, 100.0));
  explore
      ->add_option("--checkpoint-every", a->checkpointEvery,
                   "Also rewrite the .tsg every this many expansions (0: off)")
      ->capture_default_str();
  explore
      ->add_option("--checkpoint-seconds", a->checkpointSeconds,
                   "Rewrite the .tsg at least this often (0: off); it is always written after "
                   "initialisation and at the end")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1e9));
  explore->add_flag("--resume", a->resume,
                    "Continue the exploration saved in --out with its own settings");
  explore->add_flag("--mpi", a->mpi,
                    "Distribute expansions over MPI ranks: mpirun -np N throng cloth explore --mpi "
                    "… (rank 0 owns the graph, ranks 1…N−1 simulate)");
  explore->add_flag("--quiet", a->quiet, "No progress bar");
  explore->add_flag("--json", a->json, "Print the result as JSON");
  explore->add_option("--out", a->out, "The .tsg file (written atomically at every checkpoint)")
      ->required();
  explore->callback([a] { runExplore(*a); });

  auto i = std::make_shared<InfoArgs>();
  CLI::App* info = cloth->add_subcommand(
      "info", "States, primary nodes, dead ends, merge error and bytes of a .tsg or .tsc file");
  info->add_option("file", i->file, ".tsg (explored graph) or .tsc (compressed) file")->required();
  info->add_flag("--json", i->json, "Print one JSON object");
  info->add_flag("--history", i->history,
                 "With a .tsg: the largest merge error after every expansion (Fig. 7)");
  info->add_flag("--blend-motion", i->blendMotion,
                 "Also play capes along the graph and compare the p95 of the largest vertex move "
                 "in frames that cross a merge edge with other frames");
  info->callback([i] { runInfo(*i); });
}

const CommandRegistration kRegistration("cloth_explore", addClothExploreCommands);

}  // namespace
}  // namespace throng::tools
