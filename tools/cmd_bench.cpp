// `throng bench`: synthesis on the GPU vs the CPU twin (one and all threads), synthesis + render,
// and with --cloth a whole frame of a caped crowd (bench_cloth.h); medians of many frames after
// warm-up, GPU timestamps. Prints a table and writes JSON.
#include <algorithm>
#include <cstdio>
#include <iterator>
#include <memory>
#include <optional>
#include <thread>

#include <nlohmann/json.hpp>

#include "bench_cloth.h"
#include "bench_experiments.h"
#include "bench_render_loop.h"
#include "bench_rows.h"
#include "bench_scene.h"
#include "bench_twin_pairs.h"
#include "command.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/log.h"
#include "progress.h"
#include "scene_options.h"
#include "stats.h"
#include "synthesis_timer.h"

namespace throng::tools {
namespace {

// gpu: full GPU synthesis; lod; lod+cache; lod+cache+rate: with the update-rate LOD at
// --update-lag; cpu: the CPU twin; clip-sets: four clip sets against
// one; render: synthesis + render of --render-characters; frame: whole frames of
// --frame-characters with LOD + cache: wide and street camera, and overhead on a tenth of the
// crowd; render-loop: the default `throng render`, GPU and wall time per frame.
const std::vector<std::string> kRowKinds{"gpu",        "lod",       "lod+cache", "lod+cache+rate",
                                         "cpu",        "clip-sets", "render",    "frame",
                                         "render-loop"};

const Row* findRow(const std::vector<Row>& rows, const std::string& variant, uint32_t n) {
  for (const Row& r : rows)
    if (r.variant == variant && r.characters == n) return &r;
  return nullptr;
}

// The issues' targets are ratios measured in one run: print them so a reader need not divide.
void printTargetRatios(const std::vector<Row>& rows, const std::vector<TwinPairResult>& pairs,
                       unsigned threads) {
  const std::string cpuMt = threads > 1 ? concat("cpu-", threads, "-threads") : "cpu-1-thread";
  std::printf("ratios (higher is faster):\n");
  for (const Row& r : rows) {
    if (r.variant != "gpu-synthesis") continue;
    const Row* cpu = findRow(rows, cpuMt, r.characters);
    const Row* cached = findRow(rows, "gpu-synthesis-lod+cache", r.characters);
    if (cpu)
      std::printf("  %7u characters: gpu full vs %s %6.2fx", r.characters, cpuMt.c_str(),
                  cpu->synthesisMs / r.synthesisMs);
    if (cached && cpu)
      std::printf(" | lod+cache vs gpu full %6.2fx, vs %s %6.2fx",
                  r.synthesisMs / cached->synthesisMs, cpuMt.c_str(),
                  cpu->synthesisMs / cached->synthesisMs);
    std::printf("\n");
  }
  for (const TwinPairResult& p : pairs)
    std::printf("  %7u characters: gpu full vs %s, a frame of each in turn %6.2fx (%.2f to %.2f)\n",
                p.characters, cpuMt.c_str(), p.ratio.median, p.ratio.min, p.ratio.max);
}

constexpr const char* kClothSkipped =
    "cloth row skipped: no --cloth FILE.tsc (make one with `throng cloth explore --garment cape "
    "--out cape.tsg` and `throng cloth compress cape.tsg --out cape.tsc`)";

// The caped frame against its target, and where its cloth time goes.
void printClothRow(const ClothBenchResult& r, double targetMs) {
  const secondary::ClothStats& s = r.stats;
  std::printf(
      "  caped frame: %.2f ms median (min %.2f, max %.2f over %d frames), target < %.0f ms: %s\n",
      r.frameMs, r.frameMsMin, r.frameMsMax, r.frames, targetMs,
      r.frameMs < targetMs ? "met" : "NOT met");
  std::printf(
      "  cloth passes %.2f ms: advance %.2f, mark %.2f, decode %.2f, far-cape splat %.2f, draw "
      "%.2f\n",
      r.clothMs, r.advanceMs, r.markMs, r.decodeMs, r.splatMs, r.drawMs);
  std::printf(
      "  capes per level %u / %u / %u / %u (triangles … splatted), %u states decoded, %u demoted\n",
      s.capes[0], s.capes[1], s.capes[2], s.capes[3], s.usedStates, s.demoted);
}

nlohmann::json clothJson(const ClothBenchResult& r, double targetMs) {
  const secondary::ClothStats& s = r.stats;
  return {{"variant", r.variant},
          {"characters", r.characters},
          {"frames", r.frames},
          {"frame_ms_median", r.frameMs},
          {"frame_ms_min", r.frameMsMin},
          {"frame_ms_max", r.frameMsMax},
          {"target_ms", targetMs},
          {"target_met", r.frameMs < targetMs},
          {"synthesis_ms_median", r.synthesisMs},
          {"render_ms_median", r.renderMs},
          {"cloth_ms_median",
           {{"total", r.clothMs},
            {"advance", r.advanceMs},
            {"mark", r.markMs},
            {"decode", r.decodeMs},
            {"splat", r.splatMs},
            {"draw", r.drawMs}}},
          {"capes_per_level", {s.capes[0], s.capes[1], s.capes[2], s.capes[3]}},
          {"states_decoded", s.usedStates},
          {"demoted", s.demoted}};
}

// Checks the options before any row runs (a bad option or file fails first).
void checkBenchOptions(BenchOptions& o) {
  if (o.quick) {
    o.counts = {1000};
    o.frames = 5;
    o.warmup = 1;
    o.warmupSeconds = 0.0;
    o.renderCharacters = 1000;
    o.clipSetCharacters = 1000;
    o.frameCounts = {1000};
    o.size = "320x180";
  }
  if (o.frames < 1 || o.warmup < 0 || !(o.warmupSeconds >= 0.0))
    fail("--frames must be >= 1, --warmup and --warmup-seconds >= 0");
  if (o.clothOnly && o.cloth.empty()) fail("--cloth-only needs --cloth FILE.tsc");
  for (uint32_t n : o.counts)
    if (n == 0 || n > 4000000) fail("--characters: each count must be 1..4000000, got ", n);
  for (uint32_t n : o.frameCounts)
    if (n == 0 || n > 4000000) fail("--frame-characters: each count must be 1..4000000, got ", n);
  parseSize(o.size);
  if (!o.cloth.empty()) secondary::readClothDatabase(o.cloth);
  if (!o.json.empty()) ensureWritableDirectory(std::filesystem::absolute(o.json).parent_path());
  if (!o.experiments.empty()) ensureWritableDirectory(o.experiments);
  if (!o.clothOnly && o.wants("render-loop")) renderLoopFolder();
}

// What every row needs, and the rows measured so far (printed as they come).
struct BenchSession {
  const BenchOptions& o;
  const gpu::Context& context;
  const anim::ClipPair& clips;
  const anim::MotionPair& pair;
  const synth::SynthPrograms& programs;
  unsigned threads = 1;
  Progress progress;
  long long stagesDone = 0;
  std::vector<Row> rows;
  std::vector<TwinPairResult> twinPairs;

  void next(const std::string& name) { progress.stage(stagesDone++, name); }
  void report(const Row& r) {
    rows.push_back(r);
    std::printf("%-34s %9u %14.3f %12.3f\n", r.variant.c_str(), r.characters, r.synthesisMs,
                r.renderMs);
    if (r.passes)
      std::printf("  passes: root motion %.3f, coverage %.3f, cache %.3f, pose %.3f ms\n",
                  r.passes->rootMotion, r.passes->coverage, r.passes->cache, r.passes->pose);
    if (r.movedShare > 0.0)
      std::printf("  update-rate LOD at %.2f px: %.1f%% of the chunks moved per step (median)\n",
                  o.updateLag, 100.0 * r.movedShare);
    if (r.renderMs > 0.0)
      std::printf("  whole frame (synthesis + render): %.2f ms\n", r.synthesisMs + r.renderMs);
    if (r.loop)
      std::printf(
          "  wall per frame %.2f ms (mean), %.2fx the GPU frame; median %.2f ms, %.2fx; PNG "
          "encoding %.2f ms per frame on %d worker%s; prepared in %.0f ms before the first "
          "frame\n",
          r.loop->wallMs, r.loop->wallMs / r.loop->gpuMs(), r.loop->wallMedianMs,
          r.loop->wallMedianMs / r.loop->gpuMs(), r.loop->encodeMs, r.loop->encodeWorkers,
          r.loop->encodeWorkers == 1 ? "" : "s", r.loop->prepareMs);
    std::fflush(stdout);
  }
};

// The whole-frame rows' cameras, one row each per --frame-characters count.
constexpr const char* kFrameCameraNames[] = {"wide", "street", "overhead"};
constexpr long long kFrameCameras = std::size(kFrameCameraNames);

// The rows the options ask for, for the progress bar's ETA.
long long benchStageCount(const BenchOptions& o, unsigned threads) {
  if (o.clothOnly) return o.cloth.empty() ? 0 : 1;
  const long long perCount = (o.wants("gpu") ? 1 : 0) + (o.wants("lod") ? 1 : 0) +
                             (o.wants("lod+cache") ? 1 : 0) + (o.wants("lod+cache+rate") ? 1 : 0) +
                             (o.wants("cpu") ? (threads > 1 ? 2 : 1) : 0) +
                             (o.wants("gpu") && o.wants("cpu") ? 1 : 0);
  return static_cast<long long>(o.counts.size()) * perCount + (o.wants("clip-sets") ? 1 : 0) +
         (o.wants("render") ? 2 : 0) +
         (o.wants("frame") ? kFrameCameras * static_cast<long long>(o.frameCounts.size()) : 0) +
         (o.wants("render-loop") ? 1 : 0) + (o.cloth.empty() ? 0 : 1);
}

void runSynthesisRows(BenchSession& s) {
  const anim::Skeleton& skeleton = s.clips.slow.skeleton;
  for (uint32_t n : s.o.counts) {
    const std::pair<const char*, Variant> gpuRows[] = {{"gpu", Variant::Full},
                                                       {"lod", Variant::Lod},
                                                       {"lod+cache", Variant::LodCache},
                                                       {"lod+cache+rate", Variant::LodCacheRate}};
    for (const auto& [kind, variant] : gpuRows) {
      if (!s.o.wants(kind)) continue;
      s.next(concat("GPU synthesis (", kind, "), ", n, " characters"));
      s.report(benchGpuSynthesis(s.context, s.programs, s.pair, skeleton, n, s.o, variant));
    }
    if (!s.o.wants("cpu")) continue;
    s.next(concat("CPU twin, 1 thread, ", n, " characters"));
    s.report(benchCpuSynthesis(s.pair, n, 1, s.o));
    if (s.threads > 1) {
      s.next(concat("CPU twin, ", s.threads, " threads, ", n, " characters"));
      s.report(benchCpuSynthesis(s.pair, n, s.threads, s.o));
    }
    if (!s.o.wants("gpu")) continue;
    s.next(concat("GPU full path and CPU twin in turn, ", n, " characters"));
    s.twinPairs.push_back(benchFullAgainstTwin(s.context, s.programs, s.pair, skeleton, n,
                                               s.threads, twinFrames(n, s.o), s.o.warmup,
                                               s.o.warmupSeconds));
    const TwinPairResult& r = s.twinPairs.back();
    std::printf(
        "  in turn: gpu full %.3f ms, cpu twin (%u threads) %.3f ms; twin / gpu %.2fx "
        "(%.2f to %.2f over %d pairs)\n",
        r.gpuMs, r.threads, r.twinMs, r.ratio.median, r.ratio.min, r.ratio.max, r.pairs);
  }
}

void runClipSetRows(BenchSession& s) {
  s.next("four clip sets against one");
  const ClipSetBenchResult sets =
      benchClipSets(s.context, s.o.clipSetCharacters, s.o.frames, s.o.warmup, s.o.warmupSeconds);
  s.report({"gpu-synthesis-lod+cache-1-clip-set", sets.characters, sets.oneSetMs, 0.0, sets.frames,
            sets.onePasses});
  s.report({"gpu-synthesis-lod+cache-4-clip-sets", sets.characters, sets.fourSetsMs, 0.0,
            sets.frames, sets.fourPasses});
  std::printf(
      "  4 clip sets (storyboard action mix) vs 1, per frame: median %.2fx (%.2f to %.2f)\n",
      sets.ratio.median, sets.ratio.min, sets.ratio.max);
}

void runRenderRows(BenchSession& s) {
  const anim::Skeleton& skeleton = s.clips.slow.skeleton;
  if (s.o.wants("render")) {
    s.next("synthesis and render");
    s.report(benchRender(s.context, s.pair, skeleton, s.o, Variant::Full, s.o.renderCharacters));
    s.next("synthesis and render with LOD and cache");
    s.report(
        benchRender(s.context, s.pair, skeleton, s.o, Variant::LodCache, s.o.renderCharacters));
  }
  if (s.o.wants("frame"))
    for (uint32_t n : s.o.frameCounts)
      for (const char* camera : kFrameCameraNames) {
        s.next(concat("whole frame, ", n, " characters, ", camera, " camera"));
        s.report(benchRender(s.context, s.pair, skeleton, s.o, Variant::LodCache, n, camera));
      }
  if (!s.o.wants("render-loop")) return;
  s.next("the default throng render");
  const RenderRunTimes t = benchRenderLoop({s.o.device, s.o.quick});
  s.report({"throng-render-default-pngs", t.characters, t.steerMs + t.synthesisMs, t.renderMs,
            t.frames, std::nullopt, t});
}

std::optional<ClothBenchResult> runClothRow(BenchSession& s) {
  if (s.o.cloth.empty()) {
    std::printf("%s\n", kClothSkipped);
    return std::nullopt;
  }
  ClothBenchOptions c;
  c.cloth = s.o.cloth;
  c.characters = s.o.renderCharacters;
  c.size = s.o.size;
  c.frames = s.o.frames;
  c.warmup = s.o.warmup;
  c.warmupSeconds = s.o.warmupSeconds;
  s.next("caped crowd");
  ClothBenchResult cloth = benchCloth(s.context, c);
  s.report({cloth.variant, cloth.characters, cloth.synthesisMs, cloth.renderMs, cloth.frames});
  printClothRow(cloth, c.targetMs);
  return cloth;
}

void runExperiments(const BenchSession& s) {
  ExperimentOptions experiment;
  experiment.counts = s.o.counts;
  // The experiments go to a million characters where memory allows: one joint buffer on
  // the device at a time (1.2 GB at 1M × 25 joints; lavapipe's heap is 2 GiB).
  const uint64_t millionBytes = 1000000ull * s.pair.jointCount() * sizeof(synth::JointPoint);
  if (!s.o.quick && s.context.info().deviceLocalBytes >= millionBytes + millionBytes / 4 &&
      std::find(s.o.counts.begin(), s.o.counts.end(), 1000000u) == s.o.counts.end())
    experiment.counts.push_back(1000000);
  experiment.outDir = s.o.experiments;
  if (s.o.quick) experiment.frames = 8;
  runScalingExperiment(s.context, s.programs, s.pair, s.clips.slow.skeleton, experiment);
  runCacheExperiment(s.context, s.programs, s.pair, experiment);
  runHitRateExperiment(s.context, s.programs, s.pair, experiment);
}

nlohmann::json benchJson(const BenchSession& s, const std::optional<ClothBenchResult>& cloth) {
  nlohmann::json doc;
  doc["schema"] = "throng.bench";
  doc["version"] = 1;
  doc["device"] = s.context.info().name;
  doc["driver"] = s.context.info().driver;
  doc["joints_per_character"] = s.pair.jointCount();
  doc["cpu_threads"] = s.threads;
  doc["frames_measured"] = s.o.frames;
  for (const Row& r : s.rows) {
    nlohmann::json row = {{"variant", r.variant},
                          {"characters", r.characters},
                          {"synthesis_ms_median", r.synthesisMs},
                          {"render_ms_median", r.renderMs},
                          {"frames", r.frames}};
    if (r.loop) {
      row["wall_ms_per_frame"] = r.loop->wallMs;
      row["wall_median_ms_per_frame"] = r.loop->wallMedianMs;
      row["encode_ms_per_frame"] = r.loop->encodeMs;
      row["prepare_ms"] = r.loop->prepareMs;
    }
    if (r.passes)
      row["passes_ms_median"] = {{"root_motion", r.passes->rootMotion},
                                 {"coverage", r.passes->coverage},
                                 {"cache", r.passes->cache},
                                 {"pose", r.passes->pose}};
    if (r.movedShare > 0.0) {
      row["update_lag_px"] = s.o.updateLag;
      row["moved_chunk_share_median"] = r.movedShare;
    }
    doc["results"].push_back(row);
  }
  doc["twin_pairs"] = nlohmann::json::array();
  for (const TwinPairResult& p : s.twinPairs)
    doc["twin_pairs"].push_back({{"characters", p.characters},
                                 {"cpu_threads", p.threads},
                                 {"pairs", p.pairs},
                                 {"gpu_ms_median", p.gpuMs},
                                 {"twin_ms_median", p.twinMs},
                                 {"ratio_median", p.ratio.median},
                                 {"ratio_min", p.ratio.min},
                                 {"ratio_max", p.ratio.max}});
  if (cloth)
    doc["cloth"] = clothJson(*cloth, ClothBenchOptions{}.targetMs);
  else
    doc["cloth"] = {{"skipped", kClothSkipped}};
  return doc;
}

void runBench(BenchOptions& o) {
  checkBenchOptions(o);
  const anim::ClipPair clips = anim::defaultRunPair();
  const anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  gpu::ContextOptions contextOptions;
  contextOptions.device = o.device;
  gpu::Context context(contextOptions);
  const synth::SynthPrograms programs(context, pair);
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::printf("device: %s (%s)\n", context.info().name.c_str(), context.info().driver.c_str());
  std::printf("%-34s %9s %14s %12s\n", "variant", "characters", "synthesis ms", "render ms");
  // A bar with the ETA over the rows on a terminal (stderr; the table stays on stdout).
  BenchSession s{
      o, context, clips, pair, programs, threads, Progress("bench", benchStageCount(o, threads))};
  if (!o.clothOnly) {
    runSynthesisRows(s);
    if (o.wants("clip-sets")) runClipSetRows(s);
    runRenderRows(s);
  }
  const std::optional<ClothBenchResult> cloth = runClothRow(s);
  s.progress.finish();
  printTargetRatios(s.rows, s.twinPairs, threads);
  if (!o.experiments.empty()) runExperiments(s);
  if (!o.json.empty()) {
    writeTextFileAtomic(o.json, benchJson(s, cloth).dump(2) + "\n");
    std::printf("wrote %s\n", o.json.c_str());
  }
}

void addBenchCommand(CLI::App& app) {
  auto options = std::make_shared<BenchOptions>();
  CLI::App* cmd =
      app.add_subcommand("bench", "Measure synthesis (GPU vs CPU twin) and rendering speed");
  cmd->add_option("--json", options->json, "Also write the results as JSON to this file");
  cmd->add_option("--characters", options->counts, "Crowd sizes for the synthesis rows")
      ->capture_default_str();
  cmd->add_option("--frames", options->frames, "Measured frames per row (median reported)")
      ->capture_default_str();
  cmd->add_option("--warmup", options->warmup, "Frames run before measuring")
      ->capture_default_str();
  cmd->add_option("--warmup-seconds", options->warmupSeconds,
                  "...and at least this long, so a GPU's clocks are up before measuring")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 60.0));
  cmd->add_option("--render-characters", options->renderCharacters, "Crowd size of the render row")
      ->capture_default_str();
  cmd->add_option("--clip-set-characters", options->clipSetCharacters,
                  "Crowd size of the storyboard-crowd row (four clip sets against one)")
      ->capture_default_str()
      ->check(CLI::Range(1u, 4000000u));
  cmd->add_option(
         "--frame-characters", options->frameCounts,
         "Crowd sizes of the whole-frame rows (LOD + cache; wide, street and overhead camera)")
      ->capture_default_str();
  cmd->add_option("--rows", options->rows,
                  "Only these kinds of row: gpu, lod, lod+cache, lod+cache+rate, cpu, clip-sets, "
                  "render, frame, render-loop (default: all); gpu with cpu adds the two in turn, "
                  "frame by frame")
      ->check(CLI::IsMember(kRowKinds));
  cmd->add_option("--update-lag", options->updateLag,
                  "Pixels of the lod+cache+rate rows' update-rate LOD (far characters move every "
                  "few frames, drawn at most this far from where they would be)")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 100.0));
  cmd->add_option("--size", options->size, "Render size WxH")->capture_default_str();
  cmd->add_option("--device", options->device, "Vulkan device by index or name");
  cmd->add_option(
      "--cloth", options->cloth,
      "Also time a whole frame of the render crowd wearing this .tsc's capes (--lod --cache)");
  cmd->add_flag("--cloth-only", options->clothOnly, "Only the caped-crowd row (needs --cloth)");
  cmd->add_flag("--quick", options->quick, "A few frames of 1000 characters (smoke test)");
  cmd->add_option("--experiments", options->experiments,
                  "Also run the paper's experiments (cache vs N, hit rate vs bucket width) into "
                  "this directory");
  cmd->callback([options] { runBench(*options); });
}

const CommandRegistration kRegistration("bench", addBenchCommand);

}  // namespace
}  // namespace throng::tools
