#include "bench_experiments.h"

#include <bit>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <thread>

#include "core/clock.h"
#include "core/error.h"
#include "core/file_io.h"
#include "core/log.h"
#include "crowd/scenario.h"
#include "gpu/commands.h"
#include "gpu/timestamps.h"
#include "render/camera.h"
#include "stats.h"
#include "synth/cpu_synth.h"
#include "synth/crowd_synth.h"
#include "synthesis_timer.h"

namespace throng::tools {
namespace {

struct CacheRun {
  double medianMs = 0.0;
  synth::MotionCacheStats stats;
};

CacheRun runWithSpeedChanges(const gpu::Context& context, const synth::SynthPrograms& programs,
                             const anim::MotionPair& pair, uint32_t n,
                             const synth::MotionCacheOptions& cache, const ExperimentOptions& o) {
  crowd::ScenarioOptions scenario;
  scenario.characters = n;
  scenario.seed = 7;
  crowd::Crowd crowd = crowd::makeScenario(scenario);
  if (cache.enabled) anim::quantizeSpeeds(crowd.motion, cache.bucketWidth);
  synth::CrowdSynth synth = synth::makeCrowdSynth(context, pair, crowd, cache);
  synth::SpeedSchedule schedule{o.speedPeriod, 7, 0.0f, 1.0f,
                                cache.enabled ? cache.bucketWidth : 0.0f};
  SynthesisTimer timer(context);
  std::vector<double> ms;
  for (int f = 0; f < o.frames; ++f) {
    double frameMs = timer.frame(programs, synth, o.dt, schedule.advance(o.dt));
    if (f >= 2) ms.push_back(frameMs);
  }
  return {median(ms), synth::readCacheStats(synth)};
}

}  // namespace

bool plotCsv(const std::filesystem::path& csv, const std::filesystem::path& png,
             const std::string& title, const std::string& xLabel, const std::string& yLabel,
             const std::vector<std::string>& series, bool logX) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0) {
    logWarning(concat("gnuplot not found: ", png.string(),
                      " not drawn (scripts/install_deps.sh installs it)"));
    return false;
  }
  const std::filesystem::path script = temporaryPathFor(png, ".gp");
  const std::filesystem::path temporary = temporaryPathFor(png, ".png");
  std::ofstream gp(script);
  gp << "set terminal pngcairo size 900,560 font ',11' noenhanced\n"
     << "set output '" << temporary.string() << "'\n"
     << "set datafile separator ','\nset key top left\nset grid\n"
     << "set title '" << title << "'\nset xlabel '" << xLabel << "'\nset ylabel '" << yLabel
     << "'\n"
     << (logX ? "set logscale x\n" : "") << "plot ";
  for (size_t i = 0; i < series.size(); ++i)
    gp << (i ? ", " : "") << "'" << csv.string() << "' using 1:" << (i + 2)
       << " with linespoints lw 2 title '" << series[i] << "'";
  gp << "\n";
  gp.close();
  bool ok = std::system(concat("gnuplot '", script.string(), "' 2>/dev/null").c_str()) == 0;
  std::filesystem::remove(script);
  if (ok)
    commitTemporaryFile(temporary, png);
  else
    std::filesystem::remove(temporary);
  return ok;
}

void runScalingExperiment(const gpu::Context& context, const synth::SynthPrograms& programs,
                          const anim::MotionPair& pair, const anim::Skeleton& skeleton,
                          const ExperimentOptions& o) {
  const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  std::string csv =
      "characters,cpu_ms,gpu_full_ms,gpu_lod_ms,gpu_lod_cache_ms,active_joint_share\n";
  std::printf(
      "Fig. 10: synthesis time vs N (CPU %u threads, GPU all joints, GPU LOD with an orbiting "
      "camera, "
      "GPU LOD + cache)\n",
      threads);
  std::printf("%10s %10s %12s %12s %14s %14s\n", "characters", "cpu ms", "gpu full ms",
              "gpu lod ms", "lod+cache ms", "active joints");
  for (uint32_t n : o.counts) {
    crowd::ScenarioOptions scenario;
    scenario.characters = n;
    scenario.seed = 3;
    crowd::Crowd crowd = crowd::makeScenario(scenario);
    std::vector<synth::JointPoint> cpuJoints(size_t(n) * pair.jointCount());
    std::vector<double> cpuMs, fullMs, lodMs, cachedMs;
    for (int f = 0; f < std::max(3, o.frames / 4); ++f) {
      auto start = std::chrono::steady_clock::now();
      synth::stepCrowdCpu(pair, crowd, 1.0f / 30.0f, threads);
      synth::poseCrowdCpu(pair, crowd, cpuJoints, threads);
      cpuMs.push_back(millisecondsSince(start));
    }
    const float extent = crowd::scenarioExtent(scenario);
    SynthesisTimer timer(context);
    // Each variant runs the same orbit on its own synthesis, one at a time, so that a million
    // characters need one joint buffer of device memory, not three.
    auto timeVariant = [&](const synth::CrowdSynth& synth, bool lodOn) {
      std::vector<double> ms;
      for (int f = 0; f < o.frames; ++f) {
        // Orbit: a full turn over the run, height and distance of the default wide camera.
        float angle = 6.2831853f * float(f) / float(o.frames);
        render::Camera camera = render::cameraPreset("wide", extent);
        glm::vec3 offset = camera.eye - camera.target;
        float radius = glm::length(glm::vec2(offset.x, offset.z));
        camera.eye = camera.target +
                     glm::vec3(radius * std::sin(angle), offset.y, -radius * std::cos(angle));
        synth::CoverageCamera lodCamera =
            synth::coverageCamera(camera.view(), camera.fovYDegrees, 1280, 720, camera.nearPlane);
        double frameMs =
            timer.frame(programs, synth, 1.0f / 30.0f, {}, lodOn ? &lodCamera : nullptr);
        if (f >= 2) ms.push_back(frameMs);
      }
      return ms;
    };
    double activeShare = 0.0;
    fullMs = timeVariant(synth::makeCrowdSynth(context, pair, crowd), false);
    {
      synth::CrowdSynth lod =
          synth::makeCrowdSynth(context, pair, crowd, {}, {true, {}, &skeleton});
      lodMs = timeVariant(lod, true);
      auto masks = gpu::readback<synth::CoverageMask>(context, lod.masks, n);
      size_t active = 0;
      for (const synth::CoverageMask& m : masks)
        active += size_t(std::popcount(synth::maskBits(m)));
      activeShare = double(active) / (double(n) * pair.jointCount());
    }
    // The cache poses every character at its bucket's speed.
    crowd::Crowd bucketed = crowd;
    anim::quantizeSpeeds(bucketed.motion, 0.05f);
    cachedMs = timeVariant(synth::makeCrowdSynth(context, pair, bucketed,
                                                 {true, 0.05f, 20ull << 20}, {true, {}, &skeleton}),
                           true);
    std::printf("%10u %10.3f %12.3f %12.3f %14.3f %13.1f%%\n", n, median(cpuMs), median(fullMs),
                median(lodMs), median(cachedMs), 100.0 * activeShare);
    std::fflush(stdout);
    csv += concat(n, ",", median(cpuMs), ",", median(fullMs), ",", median(lodMs), ",",
                  median(cachedMs), ",", activeShare, "\n");
  }
  writeTextFileAtomic(o.outDir / "time_vs_n.csv", csv);
  plotCsv(o.outDir / "time_vs_n.csv", o.outDir / "time_vs_n.png",
          "Synthesis time per frame vs crowd size", "characters", "ms per frame (median)",
          {"CPU twin", "GPU all joints", "GPU coverage LOD", "GPU LOD + cache"}, true);
}

void runCacheExperiment(const gpu::Context& context, const synth::SynthPrograms& programs,
                        const anim::MotionPair& pair, const ExperimentOptions& o) {
  std::string csv =
      "characters,no_cache_ms,cache_ms,cache_hits,cache_misses,cache_evictions,cache_bytes,budget_"
      "bytes\n";
  std::printf(
      "Fig. 11: synthesis with and without the motion cache, speeds changing every %.1f s\n",
      o.speedPeriod);
  std::printf("%10s %14s %12s %8s %8s %10s %12s\n", "characters", "no cache ms", "cache ms", "hits",
              "misses", "evictions", "cache bytes");
  for (uint32_t n : o.counts) {
    CacheRun plain = runWithSpeedChanges(context, programs, pair, n, {}, o);
    CacheRun cached =
        runWithSpeedChanges(context, programs, pair, n, {true, 0.05f, 20ull << 20}, o);
    if (cached.stats.bytesUsed > cached.stats.budgetBytes)
      fail("motion cache exceeded its budget: ", cached.stats.bytesUsed, " > ",
           cached.stats.budgetBytes, " bytes");
    std::printf("%10u %14.3f %12.3f %8u %8u %10u %12llu\n", n, plain.medianMs, cached.medianMs,
                cached.stats.hits, cached.stats.misses, cached.stats.evictions,
                static_cast<unsigned long long>(cached.stats.bytesUsed));
    csv += concat(n, ",", plain.medianMs, ",", cached.medianMs, ",", cached.stats.hits, ",",
                  cached.stats.misses, ",", cached.stats.evictions, ",", cached.stats.bytesUsed,
                  ",", cached.stats.budgetBytes, "\n");
  }
  writeTextFileAtomic(o.outDir / "cache_vs_n.csv", csv);
  plotCsv(o.outDir / "cache_vs_n.csv", o.outDir / "cache_vs_n.png",
          "Synthesis with and without the motion cache", "characters",
          "synthesis ms per frame (median)", {"no cache", "cache"}, true);
}

void runHitRateExperiment(const gpu::Context& context, const synth::SynthPrograms& programs,
                          const anim::MotionPair& pair, const ExperimentOptions& o) {
  // A 1 MB budget holds about 20 entries of the built-in pair, so narrow buckets (more distinct
  // speeds than entries) thrash the FIFO while wide ones all stay resident; the price of wide
  // buckets is the speed quantization (mean |w − bucket speed| = width / 4).
  const uint64_t budget = 1ull << 20;
  std::string csv = "bucket_width,hit_rate,entries,misses,evictions\n";
  std::printf(
      "Cache hit rate vs bucket width (10000 characters, 1 MB budget, speeds changing every %.1f "
      "s)\n",
      o.speedPeriod);
  for (float width : {0.01f, 0.02f, 0.04f, 0.05f, 0.1f, 0.2f}) {
    CacheRun run = runWithSpeedChanges(context, programs, pair, 10000, {true, width, budget}, o);
    double rate = double(run.stats.hits) / std::max(1u, run.stats.hits + run.stats.misses);
    std::printf("  width %.2f: hit rate %.3f (%u hits, %u misses, %u evictions, %u entries)\n",
                width, rate, run.stats.hits, run.stats.misses, run.stats.evictions,
                run.stats.entries);
    csv += concat(width, ",", rate, ",", run.stats.entries, ",", run.stats.misses, ",",
                  run.stats.evictions, "\n");
  }
  writeTextFileAtomic(o.outDir / "hit_rate_vs_bucket.csv", csv);
  plotCsv(o.outDir / "hit_rate_vs_bucket.csv", o.outDir / "hit_rate_vs_bucket.png",
          "Motion cache hit rate", "bucket width (speed weight)", "hit rate per bucket lookup",
          {"hit rate"}, false);
}

}  // namespace throng::tools
