// The motion cache's classify under the update-rate LOD (synth/scheduled_classify.h): validity,
// the rule on the CPU, then the GPU against its twin step by step with a cache too small for
// every bucket (entries are evicted), and every cached character's pose source checked against
// its own bucket and phase (a pose source left naming an evicted entry would draw another
// bucket's pose).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "anim/default_clips.h"
#include "crowd/scenario.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "synth/crowd_synth.h"
#include "synth/scheduled_classify.h"
#include "synth_fixtures.h"

using namespace throng;

namespace {

synth::ClassifySchedulePush smallPush() {
  synth::ClassifySchedulePush push{};
  push.characterCount = 200;  // chunks 0..3, the last of 8 characters
  push.rowCount = 10;
  push.bucketWidth = 0.5f;  // buckets 0 (w < 0.25), 1 and 2
  push.dataBase = 100;
  push.jointCount = 3;
  push.poseChunk = 70;
  return push;
}

}  // namespace

TEST_CASE("scheduled classify: the job says what is missing") {
  synth::ScheduledClassifyJob job;
  const std::vector<std::string> problems = job.validate();
  for (const char* what :
       {"'crowd'", "'cache'", "'rate'", "'dispatchArgs'", "'poseSource'", "'characterLists'",
        "'listCounts'", "characterCount", "poseChunk", "jointCount"})
    CHECK(std::any_of(problems.begin(), problems.end(),
                      [&](const std::string& p) { return p.find(what) != std::string::npos; }));
}

TEST_CASE("scheduled classify: moved chunks are classified, or every chunk after an insert") {
  const synth::ClassifySchedulePush push = smallPush();
  std::vector<glm::vec4> motion(push.characterCount);
  for (uint32_t i = 0; i < push.characterCount; ++i)  // phase, w: bucket 0 for even characters
    motion[i] = gpu_types::makeMotion(float(i % 10) / 10.0f, i % 2 ? 1.0f : 0.0f, 0.0f, 1.0f);
  const std::vector<int32_t> bucketSlot = {-1, -1, 4};  // only the fast bucket is resident
  const uint32_t kOld = 7;                              // a pose source left from before
  std::vector<uint32_t> source(push.characterCount, kOld);
  std::vector<std::vector<uint32_t>> misses;
  const uint32_t moved[] = {3, 1};
  CHECK_FALSE(synth::classifyScheduledCpu(moved, 0, motion, bucketSlot, push, source, misses));
  REQUIRE(misses.size() == 3);  // pose chunks of 70
  for (uint32_t i = 0; i < push.characterCount; ++i) {
    CAPTURE(i);
    const bool listed = i / 64 == 1 || i / 64 == 3;
    if (!listed)
      CHECK(source[i] == kOld);
    else if (i % 2 == 0)
      CHECK(source[i] == gpu_types::kPoseInJoints);
    else
      CHECK(source[i] == 100 + (4 * 10 + (i % 10)) * 3);
  }
  // Chunk 1 is characters 64..127 (pose chunks 0 and 1), chunk 3 is 192..199 (pose chunk 2).
  CHECK(misses[0].size() == 3);   // 64, 66, 68
  CHECK(misses[1].size() == 29);  // 70..126, even
  CHECK(misses[2].size() == 4);   // 192..198, even
  CHECK(misses[2].front() == 192 - 140);
  std::fill(source.begin(), source.end(), kOld);
  CHECK(synth::classifyScheduledCpu({}, 1, motion, bucketSlot, push, source, misses));
  CHECK(std::count(source.begin(), source.end(), kOld) == 0);
}

TEST_CASE("scheduled classify: GPU equals the twin step by step, and no pose source goes stale") {
  gpu::Context& ctx = test::gpuContext();
  const anim::MotionPair& pair = test::builtInRunPair();
  crowd::ScenarioOptions scenario;
  scenario.characters = 4500;  // 71 chunks
  crowd::Crowd crowd = crowd::makeScenario(scenario);
  synth::MotionCacheOptions cacheOptions;
  cacheOptions.enabled = true;
  const synth::LodOptions lod{true, {}, &test::builtInRunSkeleton(), 2.0f};
  // Room for 4 entries: a speed epoch spreads the crowd over more buckets, so entries are
  // evicted while characters that stand still name them.
  cacheOptions.budgetBytes =
      synth::makeCrowdSynth(ctx, pair, crowd, cacheOptions, lod).front().cache.entryBytes * 4;
  synth::CrowdSynth gpuSynth = synth::makeCrowdSynth(ctx, pair, crowd, cacheOptions, lod);
  REQUIRE(gpuSynth.scheduledClassify.has_value());
  const synth::GpuMotionCache& cache = gpuSynth.front().cache;
  REQUIRE(cache.capacity == 4);
  synth::SynthPrograms programs(ctx, pair);
  const synth::SynthPrograms* used[] = {&programs};
  const uint32_t poseChunk = 1000;  // five pose chunks
  const VkDeviceSize bindingBytes =
      VkDeviceSize(poseChunk) * pair.jointCount() * sizeof(synth::JointPoint);
  synth::ClassifySchedulePush push{};
  push.characterCount = uint32_t(crowd.size());
  push.rowCount = cache.rowCount;
  push.bucketWidth = cache.options.bucketWidth;
  push.dataBase = cache.dataBase;
  push.jointCount = uint32_t(pair.jointCount());
  push.poseChunk = poseChunk;
  size_t restricted = 0, everyChunk = 0, stale = 0, sourceMismatches = 0, listMismatches = 0;
  for (int step = 0; step < 64; ++step) {
    // Far (a few chunks move per step) for 56 steps, then nearer.
    const float distance = 400.0f * std::pow(0.7f, float(std::max(step - 55, 0)));
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 0.3f * distance, -distance), glm::vec3(0.0f),
                                       glm::vec3(0, 1, 0));
    const synth::CoverageCamera camera = synth::coverageCamera(view, 45.0f, 1280, 720, 0.1f);
    // Speed epochs send the crowd to the fast buckets at step 3 and to the middle ones at step 30:
    // the characters that move ask for buckets that are not resident, whose entries evict those
    // that characters standing still name.
    anim::SpeedRetarget retarget;
    if (step == 3) retarget = {3u, 7u, 0.9f, 1.0f, 0.0f};
    if (step == 30) retarget = {30u, 7u, 0.45f, 0.55f, 0.0f};
    const auto before = gpu::readback<uint32_t>(ctx, gpuSynth.poseSource, crowd.size());
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      synth::recordSynthesis(cmd, used, gpuSynth, 1 / 30.0f, bindingBytes, retarget, &camera);
    });
    const uint32_t moved = synth::readMovedChunks(ctx, *gpuSynth.updateRate);
    const auto list = gpu::readback<glm::uvec2>(ctx, gpuSynth.updateRate->chunkList, moved);
    std::vector<uint32_t> movedChunks;
    for (const glm::uvec2& entry : list) movedChunks.push_back(entry.x);
    const uint32_t fresh = gpu::readback<uint32_t>(ctx, cache.freshSlots, 1)[0];
    const auto bucketSlot = gpu::readback<int32_t>(ctx, cache.bucketSlot, cache.bucketCount);
    const auto slotBucket = gpu::readback<int32_t>(ctx, cache.slotBucket, cache.capacity);
    crowd::Crowd now;
    crowd::downloadCrowd(ctx, gpuSynth.crowd, now);
    std::vector<uint32_t> expected = before;
    std::vector<std::vector<uint32_t>> misses;
    const bool all = synth::classifyScheduledCpu(movedChunks, fresh, now.motion, bucketSlot, push,
                                                 expected, misses);
    restricted += !all && moved < gpuSynth.updateRate->chunkCount;
    everyChunk += all;
    const auto source = gpu::readback<uint32_t>(ctx, gpuSynth.poseSource, crowd.size());
    const auto counts = gpu::readback<uint32_t>(ctx, gpuSynth.listCounts, misses.size());
    const auto lists = gpu::readback<uint32_t>(ctx, gpuSynth.characterLists, crowd.size());
    for (size_t i = 0; i < crowd.size(); ++i) {
      sourceMismatches += source[i] != expected[i];
      if (source[i] == gpu_types::kPoseInJoints) continue;
      // The entry it names holds its bucket, at the row of its phase.
      const uint32_t entry = (source[i] - cache.dataBase) / push.jointCount;
      const uint32_t bucket = synth::speedBucket(gpu_types::speedWeight(now.motion[i]),
                                                 cache.options.bucketWidth, cache.bucketCount);
      stale += slotBucket[entry / cache.rowCount] != int32_t(bucket) ||
               entry % cache.rowCount !=
                   synth::cacheRow(gpu_types::cyclePhase(now.motion[i]), cache.rowCount);
    }
    for (size_t c = 0; c < misses.size(); ++c) {
      std::vector<uint32_t> got(lists.begin() + c * poseChunk,
                                lists.begin() + c * poseChunk + counts[c]);
      std::sort(got.begin(), got.end());
      listMismatches += got != misses[c];
    }
  }
  MESSAGE("64 steps: ", restricted, " classified the moved chunks alone, ", everyChunk,
          " every chunk (an entry filled); pose sources differing from the twin ", sourceMismatches,
          ", stale ", stale, ", pose lists differing ", listMismatches);
  CHECK(restricted >= 5);
  CHECK(everyChunk >= 2);
  CHECK(sourceMismatches == 0);
  CHECK(stale == 0);
  CHECK(listMismatches == 0);
  CHECK(ctx.validationMessageCount() == 0);
}
