// Synthesis over groups: several clip sets animating contiguous ranges of ONE set of crowd
// buffers (storyboard crowds). Validity of the groups, then GPU vs the CPU twin run on the same
// ranges, with and without the motion cache (cached characters stay cached, each group's entries
// in its own part of the shared data buffer). Several groups run root motion, the cache insert
// and the cache classify in one dispatch each (group_passes.h): their FIFOs and LOD masks are
// checked against each group's own twin and pass.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/default_clips.h"
#include "core/error.h"
#include "core/rng.h"
#include "crowd/scenario.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "synth/cpu_synth.h"
#include "synth/crowd_synth.h"
#include "synth/group_passes.h"
#include "synth/motion_cache_cpu.h"
#include "synth_fixtures.h"
#include "test_support.h"

using namespace throng;

namespace {

struct Groups {
  std::vector<anim::MotionPair> pairs;
  std::vector<const anim::MotionPair*> pointers;
  std::vector<uint32_t> first;
};

// Run, walk and hop pairs over three ranges of an n-character crowd.
Groups threeGroups(uint32_t n) {
  Groups g;
  for (const anim::ClipPair& clips :
       {anim::defaultRunPair(), anim::defaultWalkPair(), anim::defaultJumpPair()})
    g.pairs.push_back(anim::makeMotionPair(clips.slow, clips.fast));
  for (const anim::MotionPair& p : g.pairs) g.pointers.push_back(&p);
  g.first = {0, n * 3 / 10, n * 7 / 10, n};
  return g;
}

crowd::Crowd groupCrowd(uint32_t n, float bucketWidth = 0.0f) {
  crowd::ScenarioOptions options;
  options.characters = n;
  crowd::Crowd crowd = crowd::makeScenario(options);
  if (bucketWidth > 0.0f)
    for (glm::vec4& m : crowd.motion) m.y = m.z = synth::quantizeSpeed(m.y, bucketWidth);
  return crowd;
}

std::vector<std::unique_ptr<synth::SynthPrograms>> groupPrograms(const Groups& g) {
  std::vector<std::unique_ptr<synth::SynthPrograms>> programs;
  for (const anim::MotionPair& p : g.pairs)
    programs.push_back(std::make_unique<synth::SynthPrograms>(test::gpuContext(), p));
  return programs;
}

std::vector<const synth::SynthPrograms*> pointers(
    const std::vector<std::unique_ptr<synth::SynthPrograms>>& programs) {
  std::vector<const synth::SynthPrograms*> out;
  for (const auto& p : programs) out.push_back(p.get());
  return out;
}

}  // namespace

TEST_CASE("crowd groups: ranges must cover the crowd in order, each with a pair") {
  gpu::Context& ctx = test::gpuContext();
  Groups g = threeGroups(100);
  crowd::Crowd crowd = groupCrowd(100);
  std::vector<uint32_t> gap = {0, 30, 60, 90};  // misses the last ten characters
  CHECK_THROWS_WITH_AS(synth::makeCrowdSynth(ctx, g.pointers, gap, crowd),
                       doctest::Contains("run from 0 to the 100 characters"), Error);
  std::vector<uint32_t> empty = {0, 30, 30, 100};
  CHECK_THROWS_WITH_AS(synth::makeCrowdSynth(ctx, g.pointers, empty, crowd),
                       doctest::Contains("group 1 has no character"), Error);
  std::vector<const anim::MotionPair*> none;
  std::vector<uint32_t> whole = {0, 100};
  CHECK_THROWS_WITH_AS(synth::makeCrowdSynth(ctx, none, whole, crowd),
                       doctest::Contains("at least one motion pair"), Error);
  synth::CrowdSynth ok = synth::makeCrowdSynth(ctx, g.pointers, g.first, crowd);
  const synth::SynthPrograms one(ctx, g.pairs[0]);
  const synth::SynthPrograms* tooFew[] = {&one};
  gpu::CommandPool pool(ctx);
  CHECK_THROWS_WITH_AS(synth::recordSynthesis(pool.allocate(), tooFew, ok, 0.03f, 1u << 27),
                       doctest::Contains("3 groups but 1 program sets"), Error);
}

TEST_CASE("crowd groups: three clip sets over one set of buffers equal the CPU twin per range") {
  gpu::Context& ctx = test::gpuContext();
  const uint32_t n = 700;
  Groups g = threeGroups(n);
  crowd::Crowd cpu = groupCrowd(n);
  synth::CrowdSynth gpuSynth = synth::makeCrowdSynth(ctx, g.pointers, g.first, cpu);
  auto programs = groupPrograms(g);
  const std::vector<const synth::SynthPrograms*> used = pointers(programs);
  // A small binding limit: several pose chunks per group.
  const VkDeviceSize chunkBytes =
      VkDeviceSize(96) * g.pairs[0].jointCount() * sizeof(synth::JointPoint);
  const float dt = 1 / 30.0f;
  std::vector<synth::JointPoint> cpuJoints(size_t(n) * g.pairs[0].jointCount());
  for (int f = 0; f < 4; ++f) {
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      synth::recordSynthesis(cmd, used, gpuSynth, dt, chunkBytes);
    });
    for (size_t k = 0; k < g.pairs.size(); ++k)
      synth::stepCrowdCpu(g.pairs[k], cpu, {g.first[k], g.first[k + 1] - g.first[k]}, dt, 2);
  }
  for (size_t k = 0; k < g.pairs.size(); ++k)
    synth::poseCrowdCpu(g.pairs[k], cpu, {g.first[k], g.first[k + 1] - g.first[k]}, cpuJoints, 2);
  auto gpuJoints = gpu::readback<synth::JointPoint>(ctx, gpuSynth.joints, cpuJoints.size());
  crowd::Crowd gpuCrowd;
  crowd::downloadCrowd(ctx, gpuSynth.crowd, gpuCrowd);
  const float joints = test::maxAbsDifference(&gpuJoints[0].positionRadius.x,
                                              &cpuJoints[0].positionRadius.x, cpuJoints.size() * 4);
  const float placement =
      test::maxAbsDifference(&gpuCrowd.placement[0].x, &cpu.placement[0].x, size_t(n) * 4);
  MESSAGE("three groups, 4 frames: max |GPU - CPU| joints ", joints, ", placement ", placement);
  CHECK(joints <= 1e-4f);
  CHECK(placement <= 1e-4f);
  // The groups really animate differently: the walk group's pelvis height differs from the
  // run group's twin output evaluated with the wrong pair.
  std::vector<synth::JointPoint> wrongPair(cpuJoints.size());
  synth::poseCrowdCpu(g.pairs[0], cpu, {g.first[1], g.first[2] - g.first[1]}, wrongPair, 2);
  const size_t from = size_t(g.first[1]) * g.pairs[0].jointCount();
  CHECK(test::maxAbsDifference(&wrongPair[from].positionRadius.x, &cpuJoints[from].positionRadius.x,
                               (size_t(g.first[2] - g.first[1])) * g.pairs[0].jointCount() * 4) >
        0.01f);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("crowd groups that steer and change speed equal the CPU twin per range") {
  // Circle steering and speed epochs are root_motion_prep.comp's, recorded per group before the
  // groups' shared root motion on the steps that need them.
  gpu::Context& ctx = test::gpuContext();
  const uint32_t n = 500;
  Groups g = threeGroups(n);
  crowd::Crowd cpu = groupCrowd(n);
  cpu.steering = anim::Steering::Circle;
  synth::CrowdSynth gpuSynth = synth::makeCrowdSynth(ctx, g.pointers, g.first, cpu);
  REQUIRE(gpuSynth.sharedPasses());
  auto programs = groupPrograms(g);
  const std::vector<const synth::SynthPrograms*> used = pointers(programs);
  const float dt = 1 / 30.0f;
  for (uint32_t f = 0; f < 40; ++f) {
    anim::SpeedRetarget retarget;
    retarget.epoch = f % 10 == 3 ? 1 + f / 10 : 0;  // new targets on four of the steps
    retarget.seed = 7;
    retarget.lo = 0.2f;
    retarget.hi = 0.9f;
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      synth::recordSynthesis(cmd, used, gpuSynth, dt, 1u << 27, retarget);
    });
    for (size_t k = 0; k < g.pairs.size(); ++k)
      synth::stepCrowdCpu(g.pairs[k], cpu, {g.first[k], g.first[k + 1] - g.first[k]}, dt, 2,
                          retarget);
  }
  crowd::Crowd gpuCrowd;
  crowd::downloadCrowd(ctx, gpuSynth.crowd, gpuCrowd);
  const float placement =
      test::maxAbsDifference(&gpuCrowd.placement[0].x, &cpu.placement[0].x, size_t(n) * 4);
  const float motion =
      test::maxAbsDifference(&gpuCrowd.motion[0].x, &cpu.motion[0].x, size_t(n) * 4);
  size_t retargeted = 0;
  const crowd::Crowd start = groupCrowd(n);
  for (uint32_t i = 0; i < n; ++i) retargeted += cpu.motion[i].z != start.motion[i].z;
  MESSAGE("three steered groups, 40 steps: max |GPU - CPU| placement ", placement, ", motion ",
          motion, "; ", retargeted, " of ", n, " targets changed");
  CHECK(placement <= 1e-4f);
  CHECK(motion <= 1e-4f);
  CHECK(retargeted > n / 2);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("crowd groups with the motion cache: cached characters stay cached, per-group entries") {
  gpu::Context& ctx = test::gpuContext();
  const uint32_t n = 900;
  Groups g = threeGroups(n);
  synth::MotionCacheOptions cache{true, 0.05f, 20ull << 20};
  crowd::Crowd crowd = groupCrowd(n, cache.bucketWidth);
  synth::CrowdSynth gpuSynth = synth::makeCrowdSynth(ctx, g.pointers, g.first, crowd, cache);
  auto programs = groupPrograms(g);
  const std::vector<const synth::SynthPrograms*> used = pointers(programs);
  for (int f = 0; f < 3; ++f)
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      synth::recordSynthesis(cmd, used, gpuSynth, 1 / 30.0f, 1u << 27);
    });
  // Every bucket became resident in the first frame: no character was synthesized in full,
  // and each points into its own group's part of the shared data.
  auto sources = gpu::readback<uint32_t>(ctx, gpuSynth.poseSource, n);
  for (size_t k = 0; k < g.pairs.size(); ++k) {
    const synth::GpuMotionCache& c = gpuSynth.groups[k].cache;
    const uint64_t begin = c.dataBase, end = begin + c.dataBytes() / sizeof(synth::JointPoint);
    for (uint32_t i = g.first[k]; i < g.first[k + 1]; ++i) {
      REQUIRE(sources[i] != gpu_types::kPoseInJoints);
      REQUIRE(sources[i] >= begin);
      REQUIRE(sources[i] < end);
    }
  }
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    synth::recordMaterializeCachedPoses(cmd, used, gpuSynth, 1u << 27);
  });
  crowd::Crowd state;
  crowd::downloadCrowd(ctx, gpuSynth.crowd, state);
  const size_t joints = g.pairs[0].jointCount();
  std::vector<synth::JointPoint> atRows(size_t(n) * joints);
  for (size_t k = 0; k < g.pairs.size(); ++k) {
    const uint32_t rows = gpuSynth.groups[k].cache.rowCount;
    crowd::Crowd rowed = state;
    for (glm::vec4& m : rowed.motion) m.x = synth::cacheRowPhase(synth::cacheRow(m.x, rows), rows);
    synth::poseCrowdCpu(g.pairs[k], rowed, {g.first[k], g.first[k + 1] - g.first[k]}, atRows, 2);
  }
  auto materialized = gpu::readback<synth::JointPoint>(ctx, gpuSynth.joints, atRows.size());
  const float worst = test::maxAbsDifference(&materialized[0].positionRadius.x,
                                             &atRows[0].positionRadius.x, atRows.size() * 4);
  const synth::MotionCacheStats stats = synth::readCacheStats(gpuSynth);
  MESSAGE("three cached groups: max |GPU - CPU at the cache rows| ", worst, "; misses ",
          stats.misses, ", hits ", stats.hits);
  CHECK(worst <= 1e-4f);
  CHECK(stats.misses == 3 * 21);  // every bucket of each clip set once
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("crowd groups: the shared passes' validity") {
  CHECK(!synth::GroupRootMotionJob{}.validate().empty());
  CHECK(!synth::GroupCoverageJob{}.validate().empty());
  CHECK(!synth::GroupInsertJob{}.validate().empty());
  CHECK(!synth::GroupClassifyJob{}.validate().empty());
  CHECK_THROWS_AS(synth::makeSynthGroupBuffers(test::gpuContext(), {}, false, false), Error);
  Groups g = threeGroups(50);
  g.pairs.push_back(g.pairs[0]);
  g.pairs.push_back(g.pairs[1]);
  g.pointers.clear();
  for (const anim::MotionPair& p : g.pairs) g.pointers.push_back(&p);
  const uint32_t five[] = {0, 10, 20, 30, 40, 50};
  CHECK_THROWS_WITH_AS(synth::makeCrowdSynth(test::gpuContext(), g.pointers, five, groupCrowd(50)),
                       "a crowd has at most 4 clip sets, got 5", Error);
}

TEST_CASE("clip set budgets: k sets share k budgets, the least needy served first") {
  const uint64_t needs[] = {10, 100, 50};
  CHECK(synth::clipSetBudgets(needs, 40) == std::vector<uint64_t>{10, 60, 50});
  const uint64_t small[] = {5, 7};
  CHECK(synth::clipSetBudgets(small, 10) == std::vector<uint64_t>{5, 7});
  const uint64_t large[] = {30, 30};
  CHECK(synth::clipSetBudgets(large, 10) == std::vector<uint64_t>{10, 10});
  const uint64_t one[] = {1000};
  CHECK(synth::clipSetBudgets(one, 10) == std::vector<uint64_t>{10});
}

namespace {
crowd::Crowd rangeOf(const crowd::Crowd& crowd, uint32_t first, uint32_t end) {
  crowd::Crowd part;
  part.placement.assign(crowd.placement.begin() + first, crowd.placement.begin() + end);
  part.motion.assign(crowd.motion.begin() + first, crowd.motion.begin() + end);
  return part;
}
}  // namespace

TEST_CASE("crowd groups over a small cache budget: each group's FIFO equals its CPU twin") {
  gpu::Context& ctx = test::gpuContext();
  const uint32_t n = 600;
  Groups g = threeGroups(n);
  // 1 MB per set holds 4 to 7 of the 21 buckets: the slow speeds' six buckets do not all fit
  // (misses that stay uncached), and as the characters move to fast targets at their cycle
  // ends, entries of slow buckets no longer in use are evicted.
  synth::MotionCacheOptions cache{true, 0.05f, 1ull << 20};
  crowd::Crowd cpu = groupCrowd(n);
  Rng rng(7);
  for (glm::vec4& m : cpu.motion) {
    m.y = synth::quantizeSpeed(rng.uniform(0.0f, 0.25f), cache.bucketWidth);
    m.z = synth::quantizeSpeed(rng.uniform(0.75f, 1.0f), cache.bucketWidth);
  }
  synth::CrowdSynth gpuSynth = synth::makeCrowdSynth(ctx, g.pointers, g.first, cpu, cache);
  auto programs = groupPrograms(g);
  const std::vector<const synth::SynthPrograms*> used = pointers(programs);
  std::vector<synth::MotionCacheCpu> twins;
  for (size_t k = 0; k < g.pairs.size(); ++k)
    twins.emplace_back(g.pairs[k], gpuSynth.groups[k].cache.options);
  const float dt = 1 / 10.0f;
  synth::MotionCacheStats before[3]{};
  for (int f = 0; f < 12; ++f) {
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      synth::recordSynthesis(cmd, used, gpuSynth, dt, 1u << 27);
    });
    auto sources = gpu::readback<uint32_t>(ctx, gpuSynth.poseSource, n);
    for (size_t k = 0; k < g.pairs.size(); ++k) {
      const uint32_t first = g.first[k], end = g.first[k + 1];
      synth::stepCrowdCpu(g.pairs[k], cpu, {first, end - first}, dt, 2);
      const crowd::Crowd part = rangeOf(cpu, first, end);
      twins[k].update(part);
      const synth::MotionCacheStats a = synth::readCacheStats(gpuSynth.groups[k].cache),
                                    b = twins[k].stats();
      CHECK(a.hits == b.hits);
      CHECK(a.misses == b.misses);
      CHECK(a.evictions == b.evictions);
      CHECK(a.entries == b.entries);
      std::vector<synth::JointPoint> scratch(g.pairs[k].jointCount());
      for (uint32_t i = first; i < end; ++i)
        REQUIRE((sources[i] != gpu_types::kPoseInJoints) ==
                twins[k].pose(part.placement[i - first], part.motion[i - first], scratch));
      if (f == 11) before[k] = a;
    }
  }
  for (size_t k = 0; k < 3; ++k) {
    MESSAGE("group ", k, ": capacity ", gpuSynth.groups[k].cache.capacity, ", hits ",
            before[k].hits, ", misses ", before[k].misses, ", evictions ", before[k].evictions);
    CHECK(gpuSynth.groups[k].cache.capacity < 21);
    CHECK(before[k].evictions > 0);
  }
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("crowd groups with LOD: the shared coverage passes equal each group's own pass") {
  gpu::Context& ctx = test::gpuContext();
  const uint32_t n = 900;
  Groups g = threeGroups(n);
  const anim::ClipPair clips = anim::defaultRunPair();
  const synth::LodOptions lod{true, {}, &clips.slow.skeleton};
  const crowd::Crowd crowd = groupCrowd(n);
  // Each group's own coverage pass (the reference), the shared coverage pass (frames with
  // walls) and root motion's shared coverage.
  synth::CrowdSynth perGroup = synth::makeCrowdSynth(ctx, g.pointers, g.first, crowd, {}, lod);
  synth::CrowdSynth separate = synth::makeCrowdSynth(ctx, g.pointers, g.first, crowd, {}, lod);
  synth::CrowdSynth fused = synth::makeCrowdSynth(ctx, g.pointers, g.first, crowd, {}, lod);
  auto programs = groupPrograms(g);
  const std::vector<const synth::SynthPrograms*> used = pointers(programs);
  size_t onScreen = 0;
  for (int f = 0; f < 20; ++f) {
    const glm::vec3 eye(4.0f * std::sin(0.1f * f), 20.0f - 0.5f * f, -40.0f + 0.8f * f);
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.3f * f, 0, 0), glm::vec3(0, 1, 0));
    const synth::CoverageCamera camera = synth::coverageCamera(view, 45.0f, 1280, 720, 0.1f);
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      CHECK(!synth::recordRootMotionPasses(cmd, used, perGroup, 1 / 30.0f));
      for (size_t k = 0; k < g.pairs.size(); ++k) {
        const synth::SynthGroup& group = perGroup.groups[k];
        synth::CoverageJob{&perGroup.crowd,
                           &group.coverageParts,
                           nullptr,
                           &perGroup.masks,
                           nullptr,
                           camera,
                           uint32_t(g.pairs[k].jointCount()),
                           group.first,
                           group.count}
            .record(cmd, used[k]->coverage);
      }
      gpu::computeToComputeBarrier(cmd);
      synth::recordPosePasses(cmd, used, perGroup, 1u << 27, &camera, nullptr, true);
      CHECK(!synth::recordRootMotionPasses(cmd, used, separate, 1 / 30.0f));
      synth::recordPosePasses(cmd, used, separate, 1u << 27, &camera);
      const bool covered = synth::recordRootMotionPasses(cmd, used, fused, 1 / 30.0f, {}, &camera);
      CHECK(covered);
      synth::recordPosePasses(cmd, used, fused, 1u << 27, &camera, nullptr, covered);
    });
    auto a = gpu::readback<synth::CoverageMask>(ctx, perGroup.masks, n);
    auto b = gpu::readback<synth::CoverageMask>(ctx, separate.masks, n);
    auto c = gpu::readback<synth::CoverageMask>(ctx, fused.masks, n);
    REQUIRE(std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
    REQUIRE(std::memcmp(a.data(), c.data(), a.size() * sizeof(a[0])) == 0);
    onScreen = 0;
    for (const synth::CoverageMask& m : a) onScreen += synth::maskBits(m) != 0;
  }
  MESSAGE("20 frames of a moving camera over 3 groups: masks equal; ", onScreen, " of ", n,
          " characters with joints in the last");
  CHECK(onScreen > n / 10);
  CHECK(ctx.validationMessageCount() == 0);
}
