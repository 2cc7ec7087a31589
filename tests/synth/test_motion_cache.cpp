// The motion cache: validity, rows, FIFO decisions and counters on a scripted sequence of
// speeds (CPU twin and GPU, frame by frame), and cached output equal to synthesis at the cache
// rows.
#include <doctest/doctest.h>

#include <algorithm>
#include <set>

#include "anim/default_clips.h"
#include "anim/reference_synth.h"
#include "core/error.h"
#include "crowd/scenario.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "synth/cpu_synth.h"
#include "synth/crowd_synth.h"
#include "synth/motion_cache_cpu.h"
#include "synth_fixtures.h"

using namespace throng;

namespace {
anim::MotionPair builtInPair() {
  anim::ClipPair clips = anim::defaultRunPair();
  return anim::makeMotionPair(clips.slow, clips.fast);
}

// A crowd whose characters all run at the given speed weights (round-robin), random phases.
crowd::Crowd crowdAt(const std::vector<float>& speeds, size_t n) {
  crowd::ScenarioOptions options;
  options.characters = static_cast<uint32_t>(n);
  crowd::Crowd crowd = crowd::makeScenario(options);
  for (size_t i = 0; i < n; ++i) crowd.motion[i].y = crowd.motion[i].z = speeds[i % speeds.size()];
  return crowd;
}
}  // namespace

TEST_CASE("CacheJob: validity") {
  synth::CacheJob job;
  auto problems = job.validate();
  REQUIRE(problems.size() == 4);
  CHECK(problems[2].find("'cache'") != std::string::npos);
  CHECK(problems[3].find("'data'") != std::string::npos);
  gpu::Context& ctx = test::gpuContext();
  anim::MotionPair pair = builtInPair();
  synth::GpuMotionCache disabled = synth::makeGpuMotionCache(ctx, pair, {});
  job.cache = &disabled;
  problems = job.validate();
  CHECK(std::find(problems.begin(), problems.end(), "the cache is disabled") != problems.end());
  // The far bodies' table and the parts that say which joints go into it come together, and
  // the table holds a FarBodyPose for every pose of the data buffer.
  synth::GpuMotionCache enabled = synth::makeGpuMotionCache(ctx, pair, {true});
  std::vector<synth::GpuMotionCache*> caches{&enabled};
  gpu::Buffer data = synth::makeCacheData(ctx, caches);
  gpu::Buffer small(ctx, 16, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  job.cache = &enabled;
  job.data = &data;
  job.farBodyPoses = &small;
  auto mentions = [](const std::vector<std::string>& list, const char* text) {
    return std::any_of(list.begin(), list.end(),
                       [&](const std::string& p) { return p.find(text) != std::string::npos; });
  };
  CHECK(mentions(job.validate(), "go together"));
  job.parts = &small;
  CHECK(mentions(job.validate(), "output 'farBodyPoses' holds 16 bytes"));
  gpu::Buffer table = synth::makeFarBodyPoses(ctx, data, uint32_t(pair.jointCount()));
  job.farBodyPoses = &table;
  CHECK_FALSE(mentions(job.validate(), "farBodyPoses"));
  CHECK_THROWS_WITH_AS(synth::validateCacheOptions({true, 0.0f, 1}),
                       doctest::Contains("--bucket-width"), Error);
}

TEST_CASE(
    "cache rows: dense in time, the nearest row within half a row of the phase, wrapping at 1") {
  anim::MotionPair pair = builtInPair();
  const uint32_t rows = synth::cacheRowCount(pair);
  const float longest = std::max(pair.slow.duration(), pair.fast.duration());
  CHECK(float(rows) >= synth::kCacheRowsPerSecond * longest);
  CHECK(rows >= uint32_t(std::max(pair.slow.frameCount, pair.fast.frameCount)));
  float worst = 0.0f;
  for (int k = 0; k < 4000; ++k) {
    float phase = (k + 0.37f) / 4000.0f;
    uint32_t row = synth::cacheRow(phase, rows);
    REQUIRE(row < rows);
    float gap = std::abs(synth::cacheRowPhase(row, rows) - phase);
    worst = std::max(worst, std::min(gap, 1.0f - gap));  // row 0 is also phase 1
  }
  CHECK(worst <= 0.5f / float(rows) + 1e-6f);
  CHECK(synth::cacheRow(0.9999999f, rows) == 0u);
  CHECK(synth::cacheRow(0.0f, rows) == 0u);
}

namespace {
// The crowd with each phase moved to the phase of its nearest cache row: what the cache shows.
crowd::Crowd atCacheRows(crowd::Crowd crowd, uint32_t rows) {
  for (glm::vec4& m : crowd.motion) m.x = synth::cacheRowPhase(synth::cacheRow(m.x, rows), rows);
  return crowd;
}
}  // namespace

TEST_CASE(
    "motion cache: FIFO order, budget and exact counters on a scripted sequence (CPU twin and "
    "GPU)") {
  gpu::Context& ctx = test::gpuContext();
  anim::MotionPair pair = builtInPair();
  synth::MotionCacheOptions options;
  options.enabled = true;
  options.bucketWidth = 0.1f;
  synth::MotionCacheCpu probe(pair, options);
  const uint64_t entryBytes = probe.stats().budgetBytes / std::max(1u, probe.capacity());
  options.budgetBytes = 2 * entryBytes + entryBytes / 2;  // room for exactly two entries
  synth::MotionCacheCpu cpu(pair, options);
  REQUIRE(cpu.capacity() == 2);

  // frame: speeds requested → expected cumulative (hits, misses, evictions)
  struct Step {
    std::vector<float> speeds;
    uint32_t hits, misses, evictions;
  };
  const Step script[] = {
      {{0.2f}, 0, 1, 0},              // miss: 0.2 inserted
      {{0.2f}, 1, 1, 0},              // hit
      {{0.4f, 0.6f}, 1, 3, 1},        // two misses, 0.2 (oldest) evicted
      {{0.2f, 0.6f}, 2, 4, 2},        // 0.6 hits; 0.2 misses again and evicts 0.4
      {{0.6f, 0.2f, 0.6f}, 4, 4, 2},  // both resident: one lookup each, whatever the count
      // Three buckets, room for two: 0.4 misses but evicts neither entry this frame uses
      // (else the FIFO would refill entries every frame, each evicting one still needed).
      {{0.2f, 0.4f, 0.6f}, 6, 5, 2},
      {{0.2f, 0.4f, 0.6f}, 8, 6, 2},
      {{0.4f}, 8, 7, 3},  // 0.4 alone: now it takes the head slot (0.6, the oldest)
  };
  crowd::Crowd crowd = crowdAt({0.2f}, 64);
  synth::SynthPrograms programs(ctx, pair);
  synth::CrowdSynth gpu = synth::makeCrowdSynth(ctx, pair, crowd, options);
  REQUIRE(gpu.front().cache.capacity == 2);
  std::vector<synth::JointPoint> cpuJoints(crowd.size() * pair.jointCount());
  for (const Step& step : script) {
    crowd = crowdAt(step.speeds, 64);
    gpu::uploadBytes(
        ctx, gpu.crowd.motion,
        {reinterpret_cast<const uint8_t*>(crowd.motion.data()), crowd.motion.size() * 16});
    gpu::uploadBytes(
        ctx, gpu.crowd.placement,
        {reinterpret_cast<const uint8_t*>(crowd.placement.data()), crowd.placement.size() * 16});
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      synth::recordSynthesis(cmd, programs, gpu, 0.0f, 1u << 27);
      synth::recordMaterializeCachedPoses(cmd, programs, gpu, 1u << 27);
    });
    cpu.update(crowd);
    synth::MotionCacheStats g = synth::readCacheStats(gpu), c = cpu.stats();
    CHECK(c.hits == step.hits);
    CHECK(c.misses == step.misses);
    CHECK(c.evictions == step.evictions);
    CHECK(g.hits == c.hits);
    CHECK(g.misses == c.misses);
    CHECK(g.evictions == c.evictions);
    CHECK(g.entries == c.entries);
    CHECK(g.bytesUsed <= options.budgetBytes);
    // Cached output: GPU equals the CPU twin, and both equal plain synthesis at that speed and
    // the phase of the cache row shown (characters whose bucket stayed uncached: at their own).
    synth::poseCrowdCpuCached(pair, cpu, crowd, cpuJoints, 2);
    std::vector<synth::JointPoint> direct(cpuJoints.size());
    crowd::Crowd shown = atCacheRows(crowd, cpu.rows());
    std::vector<synth::JointPoint> probeJoints(pair.jointCount());
    for (size_t i = 0; i < crowd.size(); ++i)
      if (!cpu.pose(crowd.placement[i], crowd.motion[i], probeJoints))
        shown.motion[i] = crowd.motion[i];
    synth::poseCrowdCpu(pair, shown, direct, 2);
    auto gpuJoints = gpu::readback<synth::JointPoint>(ctx, gpu.joints, cpuJoints.size());
    CHECK(test::maxAbsDifference(&gpuJoints[0].positionRadius.x, &cpuJoints[0].positionRadius.x,
                                 cpuJoints.size() * 4) <= 1e-4f);
    CHECK(test::maxAbsDifference(&direct[0].positionRadius.x, &cpuJoints[0].positionRadius.x,
                                 cpuJoints.size() * 4) <= 1e-4f);
  }
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE(
    "motion cache: a crowd over many frames shows synthesis at its rows, close to the uncached "
    "path") {
  gpu::Context& ctx = test::gpuContext();
  anim::MotionPair pair = builtInPair();
  synth::MotionCacheOptions options;
  options.enabled = true;
  options.bucketWidth = 0.05f;
  crowd::ScenarioOptions scenario;
  scenario.characters = 2000;
  crowd::Crowd crowd = crowd::makeScenario(scenario);
  for (glm::vec4& m : crowd.motion) m.y = m.z = synth::quantizeSpeed(m.y, options.bucketWidth);
  synth::SynthPrograms programs(ctx, pair);
  synth::CrowdSynth cached = synth::makeCrowdSynth(ctx, pair, crowd, options);
  synth::CrowdSynth plain = synth::makeCrowdSynth(ctx, pair, crowd);
  for (int f = 0; f < 5; ++f) {
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      synth::recordSynthesis(cmd, programs, cached, 1 / 30.0f, 1u << 27);
      synth::recordSynthesis(cmd, programs, plain, 1 / 30.0f, 1u << 27);
    });
  }
  // After the first frame every bucket is resident: synthesis wrote no joint for any character,
  // each points at its cache entry.
  auto sources = gpu::readback<uint32_t>(ctx, cached.poseSource, crowd.size());
  CHECK(std::count(sources.begin(), sources.end(), gpu_types::kPoseInJoints) == 0);
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    synth::recordMaterializeCachedPoses(cmd, programs, cached, 1u << 27);
  });
  size_t n = crowd.size() * pair.jointCount();
  auto a = gpu::readback<synth::JointPoint>(ctx, cached.joints, n);
  auto b = gpu::readback<synth::JointPoint>(ctx, plain.joints, n);
  // The cache shows the row nearest each phase: equal to the CPU twin synthesizing at that
  // row's phase, and within half a row's motion (1/960 s) of the continuous pose.
  crowd::Crowd state;
  crowd::downloadCrowd(ctx, cached.crowd, state);
  std::vector<synth::JointPoint> atRows(n);
  synth::poseCrowdCpu(pair, atCacheRows(state, cached.front().cache.rowCount), atRows, 2);
  float worst = test::maxAbsDifference(&a[0].positionRadius.x, &atRows[0].positionRadius.x, n * 4);
  float offRow = test::maxAbsDifference(&a[0].positionRadius.x, &b[0].positionRadius.x, n * 4);
  synth::MotionCacheStats stats = synth::readCacheStats(cached);
  MESSAGE("cache vs synthesis at the cache rows over 5 frames: max diff ", worst,
          "; vs the continuous phase ", offRow, "; hits ", stats.hits, " misses ", stats.misses,
          " entries ", stats.entries, " bytes ", stats.bytesUsed);
  CHECK(worst <= 1e-4f);
  CHECK(offRow <= 0.01f);     // 1/960 s of a run: millimetres
  CHECK(stats.misses == 21);  // every bucket of width 0.05 once
  CHECK(stats.hits == 4 * 21);
  CHECK(stats.bytesUsed <= stats.budgetBytes);
  CHECK(ctx.validationMessageCount() == 0);
}
