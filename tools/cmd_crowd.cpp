// throng crowd simulate|metrics|bench: storyboard crowds that follow path vectors taken from
// tracked people, with GPU collision avoidance, measured against the real trajectories.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "anim/default_clips.h"
#include "cli_errors.h"
#include "command.h"
#include "core/error.h"
#include "crowd/avoidance_bench.h"
#include "crowd/crowd_sim.h"
#include "crowd/trajectories.h"
#include "crowd/trajectory_writer.h"
#include "crowd/walls_file.h"
#include "gpu/context.h"
#include "scene_storyboard.h"
#include "storyboard/codec.h"
#include "storyboard/legend.h"
#include "storyboard/storyboard_placement.h"

namespace throng::tools {
namespace {
namespace sb = throng::storyboard;

// The scenes' policy names (scene_storyboard.h), their aliases, and every policy in turn.
const CLI::Validator kPolicyNames =
    oneOf("policy", {"anticipatory", "published", "none", "ttc", "rule", "all"});

// Options shared by simulate and metrics.
struct RunOptions {
  std::vector<std::string> policies{"anticipatory"};
  float seconds = 20.0f;
  float dt = 0.05f;
  float radius = 0.3f;
  float bodyRadius = crowd::kBodyRadius;
  float stepTime = 0.0f;  // seconds per annotation step; 0: by dataset
  uint64_t seed = 1;
  bool cpu = false, json = false;
  std::string device;

  void add(CLI::App* cmd, const char* policyHelp) {
    cmd->add_option("--policy", policies, policyHelp)->check(kPolicyNames);
    cmd->add_option("--dt", dt, "Simulation step in seconds, 1/n of a second (default 0.05)")
        ->check(inInterval(End::kOpen, 0, 1, End::kClosed, "seconds"));
    cmd->add_option("--radius", radius,
                    "Safe radius of each agent in metres, kept by avoidance; overlaps of it are "
                    "reported as intrusions (default 0.3)")
        ->check(inInterval(End::kOpen, 0, 10, End::kClosed, "metres"));
    cmd->add_option("--body-radius", bodyRadius,
                    "Body radius in metres; overlaps of it are the collisions (default 0.2)")
        ->check(inInterval(End::kOpen, 0, 10, End::kClosed, "metres"));
    cmd->add_option(
        "--step-time", stepTime,
        "Seconds per annotation step of the trajectories (default: 0.667 for biwi_eth, else 0.4)");
    cmd->add_option("--seed", seed,
                    "Random seed (placement jitter, source choice, the rule's turns)");
    cmd->add_flag("--cpu", cpu, "Run the CPU twin instead of the GPU passes");
    cmd->add_option("--device", device, "Vulkan device by index or name");
    cmd->add_flag("--json", json, "Print the results as JSON");
  }

  std::vector<crowd::SteerPolicy> parsedPolicies() const {
    std::vector<crowd::SteerPolicy> out;
    for (const std::string& name : policies) {
      if (name == "all") {
        out.insert(out.end(),
                   {crowd::SteerPolicy::None, crowd::SteerPolicy::Rule, crowd::SteerPolicy::Ttc});
        continue;
      }
      out.push_back(scenePolicy(name));
    }
    return out;
  }

  crowd::SimulationOptions simulation(crowd::SteerPolicy policy) const {
    if (!(seconds >= 1.0f && seconds <= 100000.0f))
      fail("--seconds ", seconds, ": expected 1..100000");
    crowd::SimulationOptions o;
    o.avoidance.policy = policy;
    o.avoidance.radius = radius;
    o.avoidance.seed = uint32_t(seed);
    o.bodyRadius = bodyRadius;
    o.dt = dt;
    o.seconds = seconds;
    return o;
  }

  crowd::TrajectoryOptions trajectoryOptions() const {
    crowd::TrajectoryOptions o;
    o.secondsPerStep = stepTime;
    return o;
  }
};

std::unique_ptr<gpu::Context> makeContext(const RunOptions& o) {
  if (o.cpu) return nullptr;
  gpu::ContextOptions options;
  options.device = o.device;
  options.quiet = o.json;
  return std::make_unique<gpu::Context>(options);
}

nlohmann::json runJson(crowd::SteerPolicy policy, const crowd::SimulationResult& r) {
  nlohmann::json j = nlohmann::json::parse(crowd::metricsJson(r.metrics));
  j["policy"] = std::string(policyName(policy));
  j["steps"] = r.steps;
  j["wall_seconds"] = r.wallSeconds;
  return j;
}

void printRun(crowd::SteerPolicy policy, const crowd::SimulationResult& r) {
  std::printf("%s", crowd::formatMetrics(concat("policy ", policyName(policy)), r.metrics).c_str());
  // Short CPU runs take milliseconds: "0.00 s" would say nothing.
  if (r.wallSeconds < 1.0)
    std::printf("  %u steps in %.1f ms wall\n", r.steps, 1000.0 * r.wallSeconds);
  else
    std::printf("  %u steps in %.2f s wall\n", r.steps, r.wallSeconds);
}

struct SimulateArgs {
  std::string storyboard, trajectories, legend, trajectoriesOut, walls;
  float cell = 0.5f, jitter = 0.1f;
  RunOptions run;
};

// --trajectories-out: every simulated frame into the writer. Frames the simulation skipped
// (nobody on the scene) are written with every agent inactive, so frame numbers stay times.
class TrajectoryRecorder : public crowd::StepObserver {
 public:
  TrajectoryRecorder(const std::string& path, float dt, std::vector<uint32_t> groups)
      : writer_(path, 1.0 / double(dt), std::move(groups)) {}

  void observe(uint64_t frame, std::span<const glm::vec4> placement,
               std::span<const uint8_t> active) override {
    if (writer_.frames() < frame) {
      const std::vector<uint8_t> nobody(placement.size(), 0);
      while (writer_.frames() < frame) writer_.addFrame(placement, nobody);
    }
    writer_.addFrame(placement, active);
  }
  void finish() { writer_.finish(); }

 private:
  crowd::TrajectoryWriter writer_;
};

// The file is checked (extension, folder, size) before the run; one run per file.
std::unique_ptr<TrajectoryRecorder> makeRecorder(const SimulateArgs& a,
                                                 const std::vector<crowd::SteerPolicy>& policies,
                                                 const sb::Placement& placed) {
  if (a.trajectoriesOut.empty()) return nullptr;
  if (policies.size() != 1)
    fail("--trajectories-out ", a.trajectoriesOut, ": records one run; give one --policy, not ",
         policies.size());
  const crowd::SimulationOptions options = a.run.simulation(policies.front());
  // Steps per second as the simulation rounds them (a bad --dt fails there, with its message).
  const uint64_t perSecond = uint64_t(std::lround(1.0 / std::max(double(options.dt), 1e-3)));
  const uint64_t frames = uint64_t(std::max(1.0f, std::floor(options.seconds))) * perSecond + 1;
  crowd::checkTrajectoryOutput(a.trajectoriesOut, placed.crowd.size(), frames);
  return std::make_unique<TrajectoryRecorder>(a.trajectoriesOut, options.dt, placed.tint);
}

void runSimulate(const SimulateArgs& a) {
  const sb::Legend legend = a.legend.empty() ? sb::Legend{} : sb::loadLegend(a.legend);
  const sb::Storyboard board = sb::readStoryboard(a.storyboard, legend, false);
  if (board.glyphs.empty()) fail(a.storyboard, ": no valid glyph, so no agent to simulate");
  const crowd::Trajectories tracks =
      crowd::loadTrajectories(a.trajectories, a.run.trajectoryOptions());
  const std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(tracks);

  const anim::ClipPair clips = anim::defaultRunPair();
  const anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  sb::PlacementOptions placeOptions;
  placeOptions.cellSize = a.cell;
  placeOptions.jitter = a.jitter;
  placeOptions.seed = a.run.seed;
  placeOptions.slowSpeed = anim::clipRootSpeed(pair.slow);
  placeOptions.fastSpeed = anim::clipRootSpeed(pair.fast);
  const sb::Placement placed = sb::placeStoryboard(board, placeOptions);

  crowd::SimulationSetup setup;
  setup.crowd = placed.crowd;
  const std::vector<uint32_t> assigned =
      crowd::assignSources(sources, placed.speedRange, a.run.seed, a.trajectories);
  std::vector<float> maxSpeed;
  for (const crowd::SpeedRange& r : placed.speedRange)
    maxSpeed.push_back(std::max(1.0f, 1.25f * r.max));
  setup.paths = crowd::followSources(setup.crowd, sources, assigned, maxSpeed);

  const std::vector<crowd::SteerPolicy> policies = a.run.parsedPolicies();
  std::optional<crowd::Obstacles> walls;
  if (!a.walls.empty()) walls = crowd::loadWalls(a.walls);
  std::unique_ptr<TrajectoryRecorder> recorder = makeRecorder(a, policies, placed);
  std::unique_ptr<gpu::Context> context = makeContext(a.run);
  nlohmann::json doc;
  doc["schema"] = "throng.crowd_simulate";
  doc["version"] = 1;
  doc["storyboard"] = a.storyboard;
  doc["trajectories"] = a.trajectories;
  doc["agents"] = board.glyphs.size();
  doc["invalid_glyphs"] = board.invalid.size();
  doc["sources"] = sources.size();
  if (walls) doc["wall_segments"] = walls->segments.size();
  doc["device"] = context ? context->info().name : std::string("cpu twin");
  if (!a.run.json)
    std::printf(
        "%s: %zu agents (%zu invalid glyphs skipped) following %zu tracked people of %s, on %s\n",
        a.storyboard.c_str(), board.glyphs.size(), board.invalid.size(), sources.size(),
        a.trajectories.c_str(), doc["device"].get<std::string>().c_str());
  if (walls && !a.run.json)
    std::printf("walls: %zu segments from %s\n", walls->segments.size(), a.walls.c_str());
  for (crowd::SteerPolicy policy : policies) {
    crowd::SimulationOptions options = a.run.simulation(policy);
    options.slowSpeed = placeOptions.slowSpeed;
    options.fastSpeed = placeOptions.fastSpeed;
    options.observer = recorder.get();
    options.walls = walls ? &*walls : nullptr;
    crowd::SimulationResult result = crowd::simulateCrowd(context.get(), setup, options);
    if (a.run.json)
      doc["runs"].push_back(runJson(policy, result));
    else
      printRun(policy, result);
  }
  if (recorder) {
    recorder->finish();
    doc["trajectories_out"] = a.trajectoriesOut;
    if (!a.run.json) std::printf("trajectories: %s\n", a.trajectoriesOut.c_str());
  }
  if (a.run.json) std::printf("%s\n", doc.dump(2).c_str());
}

void addSimulate(CLI::App& parent) {
  auto* cmd = parent.add_subcommand(
      "simulate", "Run a storyboard crowd along path vectors from tracked people");
  auto args = std::make_shared<SimulateArgs>();
  cmd->add_option("--storyboard", args->storyboard, "Storyboard PNG (glyphs)")->required();
  cmd->add_option("--trajectories", args->trajectories,
                  "Tracked people: 'frame ped x y' text or ETH obsmat.txt")
      ->required();
  cmd->add_option("--legend", args->legend,
                  "Colour legend JSON (default: the default colours of docs/formats.md)");
  cmd->add_option("--seconds", args->run.seconds, "Seconds simulated (default 20)")
      ->check(inRange(1, 100000, "seconds"));
  cmd->add_option("--cell", args->cell, "Metres per storyboard pixel (default 0.5)");
  cmd->add_option("--jitter", args->jitter, "Random offset of each agent, +- metres (default 0.1)");
  cmd->add_option("--trajectories-out", args->trajectoriesOut,
                  "Every agent's position per simulated step: FILE.txt in PedPy's 'id frame x y z' "
                  "(metres, x y = engine x z) or FILE.csv with time, heading, speed, group and "
                  "state (one --policy)");
  cmd->add_option("--walls", args->walls,
                  "Static walls: polylines, polygons and walkable rasters in metres, scene "
                  "coordinates (docs/formats.md, Walls); agents steer around them and never cross "
                  "them or come within --radius of them");
  args->run.add(cmd,
                "Avoidance: anticipatory, published, none or all (default anticipatory; ttc and "
                "rule are aliases)");
  cmd->callback([args] { runSimulate(*args); });
}

struct MetricsArgs {
  std::vector<std::string> trajectories;
  RunOptions run;
};

void runMetrics(MetricsArgs a) {
  std::unique_ptr<gpu::Context> context = makeContext(a.run);
  nlohmann::json doc;
  doc["schema"] = "throng.crowd_metrics";
  doc["version"] = 1;
  doc["device"] = context ? context->info().name : std::string("cpu twin");
  for (const std::string& file : a.trajectories) {
    const crowd::Trajectories tracks = crowd::loadTrajectories(file, a.run.trajectoryOptions());
    const std::vector<crowd::PathSource> sources = crowd::resamplePathVectors(tracks);
    crowd::SimulationSetup setup = crowd::replaySetup(sources, file);
    uint32_t span = 0;
    for (uint32_t last : setup.paths.lastSecond) span = std::max(span, last);
    const crowd::CrowdMetrics real =
        crowd::trajectoryMetrics(tracks, a.run.radius, a.run.bodyRadius);
    nlohmann::json entry;
    entry["file"] = file;
    entry["people"] = tracks.tracks.size();
    entry["sources"] = sources.size();
    entry["frame_step"] = tracks.frameStep;
    entry["seconds_per_step"] = tracks.secondsPerStep;
    entry["real"] = nlohmann::json::parse(crowd::metricsJson(real));
    if (!a.run.json) {
      std::printf("%s: %zu people (%zu span 2+ s), frame step %d = %.3f s, replay of %u s on %s\n",
                  file.c_str(), tracks.tracks.size(), sources.size(), tracks.frameStep,
                  tracks.secondsPerStep, span, doc["device"].get<std::string>().c_str());
      std::printf("%s", crowd::formatMetrics("real people", real).c_str());
    }
    for (crowd::SteerPolicy policy : a.run.parsedPolicies()) {
      crowd::SimulationOptions options = a.run.simulation(policy);
      options.seconds = a.run.seconds > 0.0f ? std::min(float(span), a.run.seconds) : float(span);
      crowd::SimulationResult result = crowd::simulateCrowd(context.get(), setup, options);
      if (a.run.json)
        entry["runs"].push_back(runJson(policy, result));
      else
        printRun(policy, result);
    }
    doc["files"].push_back(entry);
  }
  if (a.run.json) std::printf("%s\n", doc.dump(2).c_str());
}

void addMetrics(CLI::App& parent) {
  auto* cmd = parent.add_subcommand("metrics",
                                    "Replay tracked people as agents with each avoidance policy "
                                    "and compare with the real people");
  auto args = std::make_shared<MetricsArgs>();
  args->run.policies = {"all"};
  args->run.seconds = 0.0f;
  cmd->add_option("--trajectories", args->trajectories,
                  "Tracked people files ('frame ped x y' or obsmat.txt)")
      ->required();
  cmd->add_option("--seconds", args->run.seconds, "Seconds replayed (default: the whole file)");
  args->run.add(cmd,
                "Avoidance policies: anticipatory, published, none or all (default all; ttc and "
                "rule are aliases)");
  cmd->callback([args] {
    if (args->run.seconds == 0.0f) args->run.seconds = 100000.0f;
    runMetrics(*args);
  });
}

struct BenchArgs {
  std::vector<uint32_t> agents{10000, 100000};
  std::vector<std::string> policies{"published", "anticipatory"};
  int steps = 10;
  float density = 0.5f;
  std::string numbering = "grid";
  std::string device;
  bool walls = false;
};

void printBenchRow(const std::string& name, uint32_t n, const crowd::AvoidanceTiming& t) {
  std::printf("%-8s %9u %10.3f %10.3f %10.3f %10.3f %10.3f %10.3f %10.3f %10.3f %8.2f\n",
              name.c_str(), n, t.countMs, t.scanMs, t.scatterMs, t.gridMs, t.steerMs, t.totalMs,
              t.moveMs, t.cpuMs, t.cpuMs / std::max(t.totalMs, 1e-6));
  std::fflush(stdout);
}

void addBench(CLI::App& parent) {
  auto* cmd = parent.add_subcommand(
      "bench",
      "GPU time of one steering step (grid + avoidance), against the CPU twin on one thread");
  auto args = std::make_shared<BenchArgs>();
  cmd->add_option("--agents", args->agents, "Crowd sizes (default 10000 100000)")
      ->check(inRange(1, 1000000, "agents"));
  cmd->add_option("--policy", args->policies,
                  "Policies: anticipatory, published, none or all (default published "
                  "anticipatory; ttc and rule are aliases)")
      ->check(kPolicyNames);
  cmd->add_option("--steps", args->steps, "Measured steps per row (median, default 10)");
  cmd->add_option("--density", args->density, "Agents per square metre (default 0.5)");
  cmd->add_option("--numbering", args->numbering,
                  "Agent numbering: grid (spawned in grid order, as storyboards number them) or "
                  "random (default grid)")
      ->check(oneOf("numbering", {"grid", "random"}));
  cmd->add_option("--device", args->device, "Vulkan device by index or name");
  cmd->add_flag("--walls", args->walls,
                "Also time each row with walls (2 x 2 m boxes every 10 m, steering and the wall "
                "constraint), in the same run, and print the ratio");
  cmd->callback([args] {
    const crowd::BenchNumbering numbering =
        args->numbering == "grid" ? crowd::BenchNumbering::Grid : crowd::BenchNumbering::Random;
    RunOptions parse;
    parse.policies = args->policies;
    std::vector<crowd::SteerPolicy> policies = parse.parsedPolicies();
    gpu::ContextOptions options;
    options.device = args->device;
    gpu::Context context(options);
    std::printf(
        "device: %s (%s), agents numbered %s\n%-8s %9s %10s %10s %10s %10s %10s %10s %10s %10s "
        "%8s\n",
        context.info().name.c_str(), context.info().driver.c_str(),
        numbering == crowd::BenchNumbering::Grid ? "in grid order" : "at random", "policy",
        "agents", "count ms", "scan ms", "scatter ms", "grid ms", "steer ms", "total ms", "move ms",
        "cpu ms", "cpu/gpu");
    for (crowd::SteerPolicy policy : policies)
      for (uint32_t n : args->agents) {
        crowd::AvoidanceParams params;
        params.policy = policy;
        const std::string name(policyName(policy));
        crowd::AvoidanceTiming t =
            crowd::benchmarkAvoidance(context, n, params, args->steps, args->density, numbering);
        printBenchRow(name, n, t);
        if (!args->walls) continue;
        crowd::AvoidanceTiming w = crowd::benchmarkAvoidance(context, n, params, args->steps,
                                                             args->density, numbering, true);
        printBenchRow(name + "+w", n, w);
        // The step with walls (grid, steering, advance, wall constraint) over the one without.
        std::printf("  walls: %u segments (boxes), step %.3f ms vs %.3f ms: %.2fx\n",
                    w.wallSegments, w.totalMs + w.moveMs, t.totalMs + t.moveMs,
                    (w.totalMs + w.moveMs) / std::max(t.totalMs + t.moveMs, 1e-6));
        std::fflush(stdout);
      }
  });
}

void addCrowdCommands(CLI::App& app) {
  auto* crowd =
      app.add_subcommand("crowd", "Storyboard crowds on path vectors with collision avoidance");
  crowd->require_subcommand(1);
  addSimulate(*crowd);
  addMetrics(*crowd);
  addBench(*crowd);
}

const CommandRegistration kRegistration("crowd", addCrowdCommands);
}  // namespace
}  // namespace throng::tools
