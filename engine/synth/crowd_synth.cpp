#include "synth/crowd_synth.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ios>

#include "core/error.h"
#include "gpu/commands.h"
#include "shaders/synth_bindings.h"
#include "synth/gpu_types.h"

namespace throng::synth {

namespace {

void checkGroups(std::span<const anim::MotionPair* const> pairs,
                 std::span<const uint32_t> groupFirst, size_t characters) {
  if (pairs.empty()) fail("a crowd needs at least one motion pair");
  if (pairs.size() > gpu_types::kSynthMaxGroups)
    fail("a crowd has at most ", gpu_types::kSynthMaxGroups, " clip sets, got ", pairs.size());
  if (groupFirst.size() != pairs.size() + 1 || groupFirst.front() != 0 ||
      groupFirst.back() != characters)
    fail("crowd groups must run from 0 to the ", characters, " characters, one range per pair");
  for (size_t k = 0; k < pairs.size(); ++k) {
    if (!pairs[k]) fail("crowd group ", k, " has no motion pair");
    if (groupFirst[k + 1] <= groupFirst[k]) fail("crowd group ", k, " has no character");
    if (pairs[k]->jointCount() != pairs.front()->jointCount())
      fail("every clip set of a crowd needs the same joint count (", pairs[k]->jointCount(), " vs ",
           pairs.front()->jointCount(), ")");
  }
}

gpu::Buffer makeCoverageParts(const gpu::Context& context) {
  return gpu::Buffer(context, sizeof(CoverageParts), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                     gpu::MemoryUse::HostVisible);
}

void writeCoverageParts(const CrowdSynth& synth, uint32_t k, const anim::Skeleton& skeleton,
                        const CoverageThresholds& thresholds) {
  const SynthGroup& group = synth.groups[k];
  BodyParts parts = describeBodyParts(skeleton);
  setMeanCentres(parts, *group.pair);
  CoverageParts uniform = makeCoverageParts(parts, thresholds);
  std::memcpy(group.coverageParts.mapped(), &uniform, sizeof(uniform));
  if (synth.shared.coverageParts) writeGroupCoverageParts(synth.shared, k, uniform);
}

void makeUpdateRate(const gpu::Context& context, CrowdSynth& synth, const LodOptions& lod) {
  if (!synth.lod) fail("the update-rate LOD needs the coverage LOD on");
  if (synth.sharedPasses())
    fail("the update-rate LOD needs a crowd of one clip set, this one has ", synth.groups.size());
  const VkSubgroupFeatureFlags needed = VK_SUBGROUP_FEATURE_BASIC_BIT |
                                        VK_SUBGROUP_FEATURE_BALLOT_BIT |
                                        VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
  if ((context.info().computeSubgroupOperations & needed) != needed)
    fail(
        "the update-rate LOD needs subgroup ballot and arithmetic in compute shaders; this "
        "device has operations 0x",
        std::hex, context.info().computeSubgroupOperations);
  const SynthGroup& group = synth.groups.front();
  const float height = static_cast<const CoverageParts*>(group.coverageParts.mapped())->body.x;
  synth.updateRate = makeGpuUpdateRate(
      context, synth.crowd.count, makeUpdateRateParams(*group.pair, height, lod.updateLagPixels));
  synth.scheduledRootMotion = makeScheduledRootMotionProgram(context, *group.pair);
  // A workgroup moves one chunk.
  THRONG_CHECK(synth.scheduledRootMotion.localSizeX() == kUpdateChunkCharacters,
               "root_motion_scheduled.comp's workgroup must be a chunk of ", kUpdateChunkCharacters,
               " characters");
  if (synth.cached())
    synth.scheduledClassify = makeScheduledClassify(context, synth.updateRate->chunkCount);
}

void makeSharedBuffers(const gpu::Context& context, CrowdSynth& synth, const LodOptions& lod) {
  std::vector<GroupDescription> groups;
  for (const SynthGroup& g : synth.groups)
    groups.push_back({g.pair, &g.cache, g.first, g.steering});
  synth.shared = makeSynthGroupBuffers(context, groups, lod.enabled, synth.cached());
  if (lod.enabled)
    for (uint32_t k = 0; k < synth.groups.size(); ++k)
      writeCoverageParts(synth, k, *lod.skeleton, lod.thresholds);
}

void allocateCacheLists(const gpu::Context& context, CrowdSynth& synth, size_t characters) {
  // At most one chunk per character, so the counts never outgrow their buffers.
  VkDeviceSize n = std::max<VkDeviceSize>(characters, 1);
  std::vector<uint32_t> inJoints(n, gpu_types::kPoseInJoints);
  synth.poseSource = gpu::makeStorageBuffer<uint32_t>(context, inJoints);
  synth.characterLists =
      gpu::Buffer(context, n * 4, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  synth.listCounts = gpu::Buffer(context, n * 4, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  synth.dispatchArgs =
      gpu::Buffer(context, n * 12, gpu::kStorageUsage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                  gpu::MemoryUse::DeviceLocal);
}

// Characters per pose chunk: each chunk binds at most maxBindingBytes of joints and 65535
// workgroups of 64.
uint32_t poseChunk(const CrowdSynth& synth, VkDeviceSize maxBindingBytes) {
  const VkDeviceSize perCharacter = VkDeviceSize(synth.jointCount()) * sizeof(JointPoint);
  return static_cast<uint32_t>(std::max<VkDeviceSize>(
      1, std::min<VkDeviceSize>(maxBindingBytes / perCharacter, 65535u * 64u)));
}

void checkPrograms(std::span<const SynthPrograms* const> programs, const CrowdSynth& synth) {
  if (programs.size() != synth.groups.size())
    fail("synthesis: ", synth.groups.size(), " groups but ", programs.size(), " program sets");
  for (const SynthPrograms* p : programs)
    if (!p) fail("synthesis: a group has no programs");
}

std::vector<uint64_t> setBudgets(std::span<const anim::MotionPair* const> pairs,
                                 const MotionCacheOptions& cache) {
  std::vector<uint64_t> need;
  for (const anim::MotionPair* pair : pairs)
    need.push_back(uint64_t(speedBucketCount(cache.bucketWidth)) * cacheRowCount(*pair) *
                   pair->jointCount() * sizeof(JointPoint));
  return clipSetBudgets(need, cache.budgetBytes);
}

}  // namespace

std::vector<uint64_t> clipSetBudgets(std::span<const uint64_t> needBytes, uint64_t budget) {
  std::vector<uint64_t> budgets(needBytes.size(), budget);
  if (needBytes.size() < 2) return budgets;
  // Water-filling: the sets that need least get what they need, the rest share what remains.
  std::vector<size_t> order(needBytes.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return needBytes[a] < needBytes[b]; });
  uint64_t remaining = budget * needBytes.size();
  for (size_t n = 0; n < order.size(); ++n) {
    const uint64_t share = remaining / (order.size() - n);
    budgets[order[n]] = std::min(needBytes[order[n]], share);
    remaining -= budgets[order[n]];
  }
  return budgets;
}

CrowdSynth makeCrowdSynth(const gpu::Context& context,
                          std::span<const anim::MotionPair* const> pairs,
                          std::span<const uint32_t> groupFirst, const crowd::Crowd& crowd,
                          const MotionCacheOptions& cache, const LodOptions& lod) {
  checkGroups(pairs, groupFirst, crowd.size());
  if (lod.enabled && !lod.skeleton) fail("LOD needs the skeleton to find the body parts");
  CrowdSynth synth;
  synth.crowd = crowd::uploadCrowd(context, crowd);
  VkDeviceSize bytes =
      VkDeviceSize(crowd.size()) * pairs.front()->jointCount() * sizeof(JointPoint);
  synth.joints = gpu::Buffer(context, bytes, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  const std::vector<uint64_t> budgets = setBudgets(pairs, cache);
  for (size_t k = 0; k < pairs.size(); ++k) {
    SynthGroup group;
    group.pair = pairs[k];
    group.motion = uploadMotionPair(context, *pairs[k]);
    MotionCacheOptions options = cache;
    options.budgetBytes = budgets[k];
    group.cache = makeGpuMotionCache(context, *pairs[k], options);
    group.steering = crowd.steering;
    group.first = groupFirst[k];
    group.count = groupFirst[k + 1] - groupFirst[k];
    if (lod.enabled) group.coverageParts = makeCoverageParts(context);
    synth.groups.push_back(std::move(group));
  }
  if (lod.enabled)
    for (uint32_t k = 0; k < synth.groups.size(); ++k)
      writeCoverageParts(synth, k, *lod.skeleton, lod.thresholds);
  std::vector<GpuMotionCache*> caches;
  for (SynthGroup& group : synth.groups) caches.push_back(&group.cache);
  synth.cacheData = makeCacheData(context, caches);
  if (lod.enabled && cache.enabled)
    synth.farBodyPoses =
        makeFarBodyPoses(context, synth.cacheData, uint32_t(pairs.front()->jointCount()));
  if (lod.enabled) {
    synth.lod = true;
    std::vector<CoverageMask> none(std::max<size_t>(crowd.size(), 1), CoverageMask{});
    synth.masks = gpu::makeStorageBuffer<CoverageMask>(context, none);
    synth.coverageView =
        gpu::Buffer(context, sizeof(CoverageView),
                    VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                    gpu::MemoryUse::DeviceLocal);
  }
  if (cache.enabled) allocateCacheLists(context, synth, crowd.size());
  if (synth.sharedPasses()) makeSharedBuffers(context, synth, lod);  // after the caches' dataBase
  if (lod.updateLagPixels != 0.0f) makeUpdateRate(context, synth, lod);
  return synth;
}

CrowdSynth makeCrowdSynth(const gpu::Context& context, const anim::MotionPair& pair,
                          const crowd::Crowd& crowd, const MotionCacheOptions& cache,
                          const LodOptions& lod) {
  const anim::MotionPair* pairs[] = {&pair};
  const uint32_t groupFirst[] = {0u, uint32_t(crowd.size())};
  return makeCrowdSynth(context, pairs, groupFirst, crowd, cache, lod);
}

void setLodThresholds(CrowdSynth& synth, const anim::Skeleton& skeleton,
                      const CoverageThresholds& thresholds) {
  if (!synth.lod) return;
  for (uint32_t k = 0; k < synth.groups.size(); ++k)
    writeCoverageParts(synth, k, skeleton, thresholds);
}

MotionCacheStats readCacheStats(const CrowdSynth& synth) {
  MotionCacheStats total;
  for (const SynthGroup& group : synth.groups)
    total = addCacheStats(total, readCacheStats(group.cache));
  return total;
}

anim::SpeedRetarget SpeedSchedule::advance(float dt) {
  anim::SpeedRetarget retarget;
  if (period <= 0.0f) return retarget;
  auto epochOf = [&](double t) { return static_cast<uint32_t>(std::floor(t / period)); };
  uint32_t before = epochOf(time);
  time += dt;
  uint32_t after = epochOf(time);
  if (after != before) retarget = {after, seed, lo, hi, bucketWidth};
  return retarget;
}

namespace {

// This frame's camera into the buffer the shared coverage passes read.
void recordCoverageView(VkCommandBuffer cmd, const CrowdSynth& synth,
                        const CoverageCamera& lodCamera) {
  // Last frame's passes have read the camera before it is replaced.
  const CoverageView view = coverageView(lodCamera);
  gpu::computeToComputeBarrier(cmd);
  vkCmdUpdateBuffer(cmd, synth.coverageView.get(), 0, sizeof(view), &view);
  gpu::computeToComputeBarrier(cmd);
}

// The update-rate schedule of this step; recording it advances the schedule's clock.
void recordUpdateSchedule(VkCommandBuffer cmd, const GpuUpdateRate& rate, float dt) {
  UpdateScheduleJob job{&rate.chunkState, &rate.chunkList, &rate.dispatchArgs, rate.chunkCount,
                        rate.step++};
  job.sinceSeconds = advanceRecentSteps(rate.recent, dt);
  job.params = rate.params;
  job.record(cmd, rate.schedule);
}

bool recordRootMotion(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                      const CrowdSynth& synth, float dt, const anim::SpeedRetarget& retarget,
                      const CoverageCamera* lodCamera) {
  const bool coverage = synth.lod && lodCamera;
  if (coverage) recordCoverageView(cmd, synth, *lodCamera);
  if (synth.sharedPasses()) {
    GroupRootMotionJob job{&synth.shared, &synth.crowd, dt, retarget};
    if (synth.cached()) {
      job.cache = &synth.front().cache.options;
      job.bucketCount = synth.front().cache.bucketCount;
    }
    if (coverage) {
      job.coverageView = &synth.coverageView;
      job.masks = &synth.masks;
    }
    job.record(cmd, *programs.front());
    gpu::computeToComputeBarrier(cmd);
    return coverage;
  }
  for (size_t k = 0; k < synth.groups.size(); ++k) {
    const SynthGroup& g = synth.groups[k];
    RootMotionJob job{&g.motion, g.pair, &synth.crowd, g.first, g.count, dt, g.steering, retarget};
    job.cache = synth.cached() ? &g.cache : nullptr;  // its lookup step, done in the same pass
    if (coverage) {
      job.coverageView = &synth.coverageView;
      job.coverageParts = &g.coverageParts;
      job.masks = &synth.masks;
    }
    if (coverage && synth.updateRate) {
      recordUpdateSchedule(cmd, *synth.updateRate, dt);
      job.updateRate = &*synth.updateRate;
      job.scheduledProgram = &synth.scheduledRootMotion;
    }
    job.record(cmd, *programs[k]);
  }
  gpu::computeToComputeBarrier(cmd);
  return coverage;
}

// Sphere centres estimated from placement and the clip's mean pose: no dependency on this
// frame's pose pass, which the masks then trim.
void recordCoverage(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                    const CrowdSynth& synth, const CoverageCamera& lodCamera) {
  if (synth.sharedPasses()) {
    recordCoverageView(cmd, synth, lodCamera);
    GroupCoverageJob{&synth.shared, &synth.crowd, &synth.coverageView, &synth.masks}.record(
        cmd, *programs.front());
    gpu::computeToComputeBarrier(cmd);
    return;
  }
  for (size_t k = 0; k < synth.groups.size(); ++k) {
    const SynthGroup& g = synth.groups[k];
    CoverageJob coverage{&synth.crowd, &g.coverageParts,   nullptr, &synth.masks, nullptr,
                         lodCamera,    synth.jointCount(), g.first, g.count};
    coverage.record(cmd, programs[k]->coverage);
  }
  gpu::computeToComputeBarrier(cmd);
}

// Pose chunks are numbered across groups: each group's first chunk, then the total.
std::vector<uint32_t> firstChunks(const CrowdSynth& synth, uint32_t chunk) {
  std::vector<uint32_t> first{0u};
  for (const SynthGroup& g : synth.groups)
    first.push_back(first.back() + (g.count + chunk - 1) / chunk);
  return first;
}

// The classify pass of each group, over its pose chunks (numbered across groups).
void recordGroupClassify(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                         const CrowdSynth& synth, uint32_t chunk) {
  uint32_t c = 0;
  for (size_t k = 0; k < synth.groups.size(); ++k) {
    const SynthGroup& g = synth.groups[k];
    for (uint32_t first = g.first; first < g.first + g.count; first += chunk, ++c) {
      CachePush push{};
      push.characterCount = std::min(chunk, g.first + g.count - first);
      push.rowCount = g.cache.rowCount;
      push.bucketWidth = g.cache.options.bucketWidth;
      push.firstCharacter = first;
      push.chunk = c;
      push.dataBase = g.cache.dataBase;
      push.jointCount = synth.jointCount();
      gpu::Binding bindings[] = {
          gpu::uniformTexelBinding(gpu_types::kCacheClassifyBindingMotion,
                                   synth.crowd.motionTexels.get()),
          gpu::storageBinding(gpu_types::kCacheClassifyBindingBucketSlot, g.cache.bucketSlot),
          gpu::storageBinding(gpu_types::kCacheClassifyBindingCharacterList, synth.characterLists),
          gpu::storageBinding(gpu_types::kCacheClassifyBindingListCounts, synth.listCounts),
          gpu::storageBinding(gpu_types::kCacheClassifyBindingPoseSource, synth.poseSource)};
      gpu::dispatch(cmd, programs[k]->cacheClassify, bindings, push, push.characterCount);
    }
  }
}

// The same over every group in one dispatch.
void recordSharedClassify(VkCommandBuffer cmd, const SynthPrograms& programs,
                          const CrowdSynth& synth, uint32_t chunk) {
  GroupClassifyJob job{&synth.shared,
                       &synth.crowd,
                       &synth.characterLists,
                       &synth.listCounts,
                       &synth.poseSource,
                       chunk,
                       synth.jointCount(),
                       synth.front().cache.bucketCount,
                       synth.front().cache.options.bucketWidth};
  job.firstChunk = firstChunks(synth, chunk);
  job.firstChunk.pop_back();  // the total
  job.record(cmd, programs);
}

// The classify over the chunks this step's schedule moved (one clip set).
void recordScheduledClassify(VkCommandBuffer cmd, const CrowdSynth& synth, uint32_t chunk) {
  const SynthGroup& g = synth.front();
  ScheduledClassifyJob job{&synth.crowd,
                           &g.cache,
                           &*synth.updateRate,
                           &synth.scheduledClassify->dispatchArgs,
                           &synth.poseSource,
                           &synth.characterLists,
                           &synth.listCounts,
                           g.count,
                           chunk,
                           synth.jointCount()};
  job.record(cmd, *synth.scheduledClassify);
}

// The cache passes of every group (the lookup was done by root motion), then the classify pass
// over each group's pose chunks (numbered across groups), or over the chunks the update-rate
// schedule moved when `scheduled`, then their indirect dispatch arguments.
void recordCacheClassify(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                         const CrowdSynth& synth, uint32_t chunk, uint32_t chunkTotal,
                         bool scheduled) {
  std::vector<CacheJob> jobs;
  for (const SynthGroup& g : synth.groups) {
    jobs.push_back({&g.motion, &synth.crowd, &g.cache, &synth.cacheData, g.first, g.count});
    if (synth.farBodyPoses) {
      jobs.back().parts = &g.coverageParts;
      jobs.back().farBodyPoses = &synth.farBodyPoses;
    }
  }
  // Each step for every group, then one barrier.
  if (synth.sharedPasses()) {
    GroupInsertJob insert{&synth.shared, {}};
    for (const SynthGroup& g : synth.groups) insert.caches.push_back(&g.cache);
    insert.record(cmd, *programs.front());
  } else {
    jobs.front().recordInsert(cmd, *programs.front());
  }
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT);
  for (size_t k = 0; k < jobs.size(); ++k) jobs[k].recordFill(cmd, *programs[k]);
  vkCmdFillBuffer(cmd, synth.listCounts.get(), 0, VkDeviceSize(chunkTotal) * 4, 0u);
  gpu::computeToComputeBarrier(cmd);
  if (scheduled) {
    recordScheduledClassify(cmd, synth, chunk);
  } else if (synth.sharedPasses()) {
    recordSharedClassify(cmd, *programs.front(), synth, chunk);
  } else {
    recordGroupClassify(cmd, programs, synth, chunk);
  }
  gpu::computeToComputeBarrier(cmd);
  gpu::Binding argBindings[] = {
      gpu::storageBinding(gpu_types::kCacheArgsBindingListCounts, synth.listCounts),
      gpu::storageBinding(gpu_types::kCacheArgsBindingDispatchArgs, synth.dispatchArgs)};
  gpu::dispatch(cmd, programs.front()->cacheArgs, argBindings, chunkTotal, chunkTotal);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT);
}

void recordPose(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                const CrowdSynth& synth, uint32_t chunk, bool lod) {
  const VkDeviceSize perCharacter = VkDeviceSize(synth.jointCount()) * sizeof(JointPoint);
  const bool cached = synth.cached();
  uint32_t c = 0;
  for (size_t k = 0; k < synth.groups.size(); ++k) {
    const SynthGroup& g = synth.groups[k];
    for (uint32_t first = g.first; first < g.first + g.count; first += chunk, ++c) {
      PoseJob pose{&g.motion,
                   &synth.crowd,
                   &synth.joints,
                   first,
                   std::min(chunk, g.first + g.count - first),
                   VkDeviceSize(first) * perCharacter};
      pose.masks = lod ? &synth.masks : nullptr;
      if (cached) {
        pose.characterList = &synth.characterLists;
        pose.listCounts = &synth.listCounts;
        pose.dispatchArgs = &synth.dispatchArgs;
        pose.listBase = first;  // the characters whose bucket is not resident
        pose.countIndex = c;
        pose.argsOffset = VkDeviceSize(c) * 12;
      }
      pose.record(cmd, *programs[k]);
    }
  }
}

}  // namespace

bool recordRootMotionPasses(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                            const CrowdSynth& synth, float dt, const anim::SpeedRetarget& retarget,
                            const CoverageCamera* lodCamera) {
  checkPrograms(programs, synth);
  return recordRootMotion(cmd, programs, synth, dt, retarget, lodCamera);
}

void recordPosePasses(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                      const CrowdSynth& synth, VkDeviceSize maxBindingBytes,
                      const CoverageCamera* lodCamera, gpu::TimestampPool* passMarks,
                      bool coverageDone) {
  checkPrograms(programs, synth);
  auto mark = [&] {
    if (passMarks) passMarks->write(cmd);
  };
  const bool lod = synth.lod && lodCamera;
  if (lod && !coverageDone) recordCoverage(cmd, programs, synth, *lodCamera);
  mark();
  const uint32_t chunk = poseChunk(synth, maxBindingBytes);
  // Root motion with its coverage ran on the schedule (recordRootMotion).
  const bool scheduled = coverageDone && synth.scheduledClassify.has_value();
  if (synth.cached())
    recordCacheClassify(cmd, programs, synth, chunk, firstChunks(synth, chunk).back(), scheduled);
  mark();
  recordPose(cmd, programs, synth, chunk, lod);
  mark();
  // The cache counters are read on the host after the frame.
  if (synth.cached())
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
}

void recordSynthesis(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                     const CrowdSynth& synth, float dt, VkDeviceSize maxBindingBytes,
                     const anim::SpeedRetarget& retarget, const CoverageCamera* lodCamera) {
  const bool covered = recordRootMotionPasses(cmd, programs, synth, dt, retarget, lodCamera);
  recordPosePasses(cmd, programs, synth, maxBindingBytes, lodCamera, nullptr, covered);
}

void recordSynthesis(VkCommandBuffer cmd, const SynthPrograms& programs, const CrowdSynth& synth,
                     float dt, VkDeviceSize maxBindingBytes, const anim::SpeedRetarget& retarget,
                     const CoverageCamera* lodCamera) {
  const SynthPrograms* one[] = {&programs};
  recordSynthesis(cmd, one, synth, dt, maxBindingBytes, retarget, lodCamera);
}

void recordMaterializeCachedPoses(VkCommandBuffer cmd,
                                  std::span<const SynthPrograms* const> programs,
                                  const CrowdSynth& synth, VkDeviceSize maxBindingBytes) {
  if (!synth.cached()) return;
  checkPrograms(programs, synth);
  const VkDeviceSize perCharacter = VkDeviceSize(synth.jointCount()) * sizeof(JointPoint);
  const uint32_t chunk = poseChunk(synth, maxBindingBytes);
  for (size_t k = 0; k < synth.groups.size(); ++k) {
    const SynthGroup& g = synth.groups[k];
    for (uint32_t first = g.first; first < g.first + g.count; first += chunk) {
      MaterializeCachedJob job{&synth.crowd,
                               &g.cache,
                               &synth.cacheData,
                               &synth.poseSource,
                               &synth.joints,
                               first,
                               std::min(chunk, g.first + g.count - first),
                               VkDeviceSize(first) * perCharacter,
                               synth.lod ? &synth.masks : nullptr};
      job.record(cmd, *programs[k]);
    }
  }
  gpu::computeToComputeBarrier(cmd);
}

void recordMaterializeCachedPoses(VkCommandBuffer cmd, const SynthPrograms& programs,
                                  const CrowdSynth& synth, VkDeviceSize maxBindingBytes) {
  const SynthPrograms* one[] = {&programs};
  recordMaterializeCachedPoses(cmd, one, synth, maxBindingBytes);
}

}  // namespace throng::synth
