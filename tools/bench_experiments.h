#pragma once
// The paper's experiments reproduced by `throng bench --experiments DIR`: CSV files and gnuplot
// PNG plots in DIR.
#include <filesystem>
#include <vector>

#include "anim/motion_texture.h"
#include "gpu/context.h"
#include "synth/synth_jobs.h"

namespace throng::tools {

struct ExperimentOptions {
  std::vector<uint32_t> counts{1000, 10000, 100000};
  int frames = 40;
  float dt = 0.25f;            // simulated seconds per frame: speed changes every 20 frames
  float speedPeriod = 5.0f;    // paper: every 5 s
  std::filesystem::path outDir;
};

// Fig. 10: synthesis time vs N for the CPU twin (all threads), the GPU with all joints and the GPU
// with coverage LOD under a camera orbiting the crowd (levels change every frame). Writes
// time_vs_n.csv (+ .png).
void runScalingExperiment(const gpu::Context& context, const synth::SynthPrograms& programs,
                          const anim::MotionPair& pair, const anim::Skeleton& skeleton,
                          const ExperimentOptions& options);

// Fig. 11: synthesis time with and without the motion cache as N grows, speeds changing every
// 5 s. Writes cache_vs_n.csv (+ .png).
void runCacheExperiment(const gpu::Context& context, const synth::SynthPrograms& programs,
                        const anim::MotionPair& pair, const ExperimentOptions& options);

// Cache hit rate (per bucket lookup) vs bucket width. Writes hit_rate_vs_bucket.csv (+ .png).
void runHitRateExperiment(const gpu::Context& context, const synth::SynthPrograms& programs,
                          const anim::MotionPair& pair, const ExperimentOptions& options);

// Runs gnuplot on a small script; returns false (and says so) when gnuplot is missing.
bool plotCsv(const std::filesystem::path& csv, const std::filesystem::path& png, const std::string& title,
             const std::string& xLabel, const std::string& yLabel, const std::vector<std::string>& series,
             bool logX);

}  // namespace throng::tools
