// throng cloth compress: an explored secondary motion graph (.tsg) → a compressed playback
// database (.tsc): SVD bases chosen by error (within a size budget), rescaled, quantized to 8/16
// bits at a length quantum, 16-bit coefficients in per-basis steps, entropy-coded in the file
// (Kim et al. 2013, §6). `cloth explore` and `cloth info` live in
// cmd_cloth.cpp; both files get-or-create the `cloth` parent command.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "cli_errors.h"
#include "command.h"
#include "core/binary_io.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/log.h"
#include "progress.h"
#include "secondary/offline/cloth_compress.h"
#include "secondary/offline/explore_file.h"
#include "secondary/offline/secondary_graph.h"
#include "synth/motion_cache.h"

namespace throng::tools {
namespace {
namespace sec = throng::secondary;
using nlohmann::json;

struct CompressArgs {
  std::string in, out;
  uint32_t bases = 0;
  float targetError = 0.002f;
  // --min-ratio, not this cap, limits the bases on explored capes (590 on the 22,968-frame one).
  uint32_t maxBases = 1000;
  float quantum = 300e-6f;
  // 0.3 mm: measured at 100:1 on the 22,968-frame damped cape, the max error is 8.9 / 6.6 / 5.6 /
  // 5.9 mm with coefficient steps of 1 / 0.5 / 0.3 / 0.2 mm (825 / 715 / 590 / 456 bases).
  float coefficientQuantum = 0.0003f;
  double minRatio = 100.0;      // the goal: the error target picks fewer bases when it can
  uint32_t reweightPasses = 1;  // a second pass over-corrects (measured on the damped cape)
  uint32_t refineSteps = 4096;  // per state; the damped cape needs ≈ 2–3 on average
  uint32_t powerIterations = 1;
  uint64_t seed = 1;
  unsigned threads = 0;
  std::optional<float> bucketWidth;
  bool json = false, quiet = false;
  bool strict = false;            // a missed --target-error is an error and nothing is written
  bool targetErrorGiven = false;  // set from the command line: --bases alone sets no target
};

// The stages compressCloth announces, in order; "reweight" and "refine" run only when needed.
constexpr const char* kStages[] = {"mean",     "svd",    "bases", "quantize",
                                   "reweight", "refine", "error"};

// The run graph's bucket width: the option, else the cape's config, else the width that gives
// the graph's bucket count (buckets 0 … B−1 at w = b / (B − 1)).
float bucketWidthOf(const CompressArgs& a, const sec::ExploreFile& file) {
  if (a.bucketWidth) return *a.bucketWidth;
  const json& garment = file.config.contains("garment") ? file.config["garment"] : json::object();
  if (garment.value("name", "") == "cape" && garment.contains("cape") &&
      garment["cape"].contains("bucket_width"))
    return garment["cape"]["bucket_width"].get<float>();
  uint32_t buckets = 0;
  for (const sec::PrimaryNode& n : file.primary.nodes)
    if (n.clip == 0) buckets = std::max(buckets, n.bucket + 1);
  return buckets > 1 ? 1.0f / float(buckets - 1) : 1.0f;
}

std::string formatMillimetres(double metres) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f mm", 1000.0 * metres);
  return text;
}

// Whether the result must meet --target-error: always when the error picks the basis count.
bool targetApplies(const CompressArgs& a) {
  return a.targetError > 0.0f && (a.bases == 0 || a.targetErrorGiven);
}

bool targetMissed(const CompressArgs& a, const sec::CompressionReport& r) {
  return targetApplies(a) && r.maxError > a.targetError;
}

// The result's largest error against the target, in the words of the warning and the error.
std::string targetMessage(const sec::CompressionReport& r, float target) {
  return concat("max reconstruction error ", formatMillimetres(r.maxError),
                " misses --target-error ", formatMillimetres(target));
}

json reportJson(const sec::ClothDatabase& db, const CompressArgs& a, double seconds) {
  json j = sec::compressionReportJson(db);
  j["schema"] = "throng.cloth_compress";
  j["version"] = 1;
  j["target_met"] = !targetMissed(a, db.report);
  j["input"] = a.in;
  j["output"] = a.out;
  j["seconds"] = seconds;
  const sec::CompressionReport& r = db.report;
  j["refine"] = {{"states_above_target", r.statesAboveTarget},
                 {"states_refined", r.statesRefined},
                 {"steps", r.refineSteps}};
  return j;
}

void runCompress(const CompressArgs& a) {
  if (!(a.minRatio >= 0.0)) fail("--min-ratio ", a.minRatio, ": expected ≥ 0 (0: no size cap)");
  const std::filesystem::path outPath = a.out;
  // Refuse an output that cannot be written (a directory, an unwritable folder) before the long
  // part, and clear what a killed earlier run left behind.
  for (const std::filesystem::path& stale : prepareOutputFile(outPath, "--out"))
    if (!a.quiet)
      std::fprintf(stderr, "removed %s (left by a run that was killed)\n", stale.c_str());

  const auto start = std::chrono::steady_clock::now();
  sec::ExploreFile file = sec::loadExploreFile(a.in);
  const sec::SecondaryGraph& g = file.graph;
  if (g.stateCount() == 0) fail(a.in, ": the graph has no cloth states");
  sec::PlaybackGraph playback = sec::playbackGraph(g);
  sec::PlaybackPrimary primary = sec::playbackPrimary(file.primary, bucketWidthOf(a, file));

  sec::ClothFrames frames;
  frames.stateCount = g.stateCount();
  frames.vertexCount = g.vertexCount;
  frames.positions = [&g](uint32_t s, std::span<glm::vec3> out) {
    sec::FrameView f = g.frame(s);
    std::copy(f.positions.begin(), f.positions.end(), out.begin());
  };
  sec::CompressOptions options;
  options.bases = a.bases;
  options.targetError = a.targetError;
  options.maxBases = a.maxBases;
  options.quantum = a.quantum;
  options.coefficientQuantum = a.coefficientQuantum;
  options.minRatio = a.minRatio;
  options.reweightPasses = a.reweightPasses;
  options.refineSteps = a.targetError > 0.0f ? a.refineSteps : 0;
  options.powerIterations = a.powerIterations;
  options.seed = a.seed;
  options.threads = a.threads;
  // The stages are all compressCloth reports: the bar counts them (the SVD and the refinement
  // take most of the time, so the ETA is rough).
  std::optional<Progress> progress;
  if (!a.quiet) {
    std::fprintf(stderr, "compress: %u cloth frames × %u vertices\n", frames.stateCount,
                 frames.vertexCount);
    progress.emplace("compress", std::size(kStages));
    options.progress = [&](const char* stage) {
      const auto at = std::find_if(std::begin(kStages), std::end(kStages),
                                   [&](const char* s) { return std::string_view(s) == stage; });
      progress->stage(at - std::begin(kStages), stage);
    };
  }
  options.clips = file.clips;
  sec::ClothDatabase db = sec::compressCloth(frames, file.mesh.triangles, std::move(primary),
                                             std::move(playback), options);
  if (progress) {
    progress->stage(std::size(kStages), "done");
    progress->finish();
  }
  const bool missed = targetMissed(a, db.report);
  if (missed && a.strict)
    fail("--strict: ", targetMessage(db.report, a.targetError), "; ", a.out, " not written");
  sec::writeClothDatabase(outPath, db);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (missed) logWarning(targetMessage(db.report, a.targetError));

  json report = reportJson(db, a, seconds);
  if (a.json) {
    std::cout << report.dump(2) << '\n';
    return;
  }
  const sec::CompressionReport& r = db.report;
  std::printf("%s → %s: %u cloth frames × %u vertices, %u bases (%u at 8 bits, %u at 16)\n",
              a.in.c_str(), a.out.c_str(), r.states, r.vertices, r.bases, r.bases8, r.bases16);
  std::printf("  raw float32 %.2f MB → stored %.3f MB: %.1f:1\n", r.rawBytes / 1e6,
              r.storedBytes / 1e6, r.ratio());
  std::printf(
      "  max reconstruction error %.3f mm (%.3f mm before quantization at %.0f µm, coefficients at "
      "%.0f µm), mean %.3f mm; %.1f s\n",
      1000.0 * r.maxError, 1000.0 * r.maxErrorBeforeQuantization, 1e6 * r.quantum,
      1e6 * r.coefficientQuantum, 1000.0 * r.meanError, seconds);
  if (r.statesAboveTarget)
    std::printf(
        "  %u states above %.3f mm after quantization: %u refined by %llu coefficient steps\n",
        r.statesAboveTarget, 1000.0 * r.targetError, r.statesRefined,
        static_cast<unsigned long long>(r.refineSteps));
}

CLI::App* clothCommand(CLI::App& app) {
  // Shared with tools/cmd_cloth.
  return commandGroup(app, "cloth", "Secondary motion: cloth exploration, compression, info");
}

void addClothCompressCommand(CLI::App& app) {
  CLI::App* cloth = clothCommand(app);
  auto a = std::make_shared<CompressArgs>();
  CLI::App* cmd = cloth->add_subcommand("compress",
                                        "Compress an explored graph (.tsg) into a playback "
                                        "database (.tsc): SVD + 8/16-bit quantization");
  cmd->add_option("graph", a->in, "The explored secondary motion graph (.tsg)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out,-o", a->out, "The compressed database (.tsc, written atomically)")
      ->required();
  cmd->add_option("--bases", a->bases,
                  "Number of bases (default: the fewest meeting --target-error)")
      ->check(CLI::Range(0, 4096));
  cmd->add_option("--target-error", a->targetError,
                  "Largest vertex error (m): picks the basis count, and the reweighting and the "
                  "coefficient refinement aim at it")
      ->capture_default_str()
      ->check(inInterval(End::kOpen, 0, kNoEnd, End::kOpen, "metres"));
  cmd->add_option("--reweight-passes", a->reweightPasses,
                  "SVD passes reweighted towards the worst states when the bases miss the target")
      ->capture_default_str()
      ->check(CLI::Range(0, 8));
  cmd->add_option("--refine-steps", a->refineSteps,
                  "Coefficient steps per state chosen for its largest error (0: none)")
      ->capture_default_str();
  cmd->add_option("--max-bases", a->maxBases, "Cap on the basis count chosen by error")
      ->capture_default_str()
      ->check(CLI::Range(1, 4096));
  cmd->add_option(
         "--quantum", a->quantum,
         "Length quantum (m): a basis takes 8 bits when its range × m_i / 255 fits it, else 16")
      ->capture_default_str()
      ->check(inInterval(End::kOpen, 0, 1, End::kOpen, "metres"));
  cmd->add_option("--coefficient-quantum", a->coefficientQuantum,
                  "Largest vertex move (m) of one coefficient step (0: full 16-bit coefficients)")
      ->capture_default_str()
      ->check(inInterval(End::kClosed, 0, 1, End::kOpen, "metres"));
  cmd->add_option("--min-ratio", a->minRatio,
                  "Keep raw/stored bytes at least this: fewer bases when needed (0: no cap)")
      ->capture_default_str();
  cmd->add_option("--power-iterations", a->powerIterations, "Randomized SVD power iterations")
      ->capture_default_str();
  cmd->add_option("--seed", a->seed, "Seed of the randomized SVD")->capture_default_str();
  cmd->add_option("--threads", a->threads, "Threads (0: all cores)");
  cmd->add_option("--bucket-width", a->bucketWidth,
                  "Speed-bucket width of the run graph (default: the garment's, else from the "
                  "graph's bucket count)")
      ->check(inInterval(End::kOpen, 0, 1, End::kClosed));
  cmd->add_flag("--json", a->json, "Print the report as JSON");
  cmd->add_flag("--quiet", a->quiet, "No progress bar or lines");
  cmd->add_flag("--strict", a->strict,
                "A result above --target-error is an error (exit 1) and no file is written");
  cmd->callback([a, cmd] {
    a->targetErrorGiven = cmd->count("--target-error") > 0;
    runCompress(*a);
  });
}

const CommandRegistration kRegistration("cloth_compress", addClothCompressCommand);

}  // namespace
}  // namespace throng::tools
