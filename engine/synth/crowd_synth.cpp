#include "synth/crowd_synth.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "gpu/commands.h"
#include "synth/gpu_types.h"

namespace throng::synth {

void setLodThresholds(CrowdSynth& synth, const anim::Skeleton& skeleton,
                      const CoverageThresholds& thresholds) {
  BodyParts parts = describeBodyParts(skeleton);
  setMeanCentres(parts, *synth.pair);
  CoverageParts uniform = makeCoverageParts(parts, thresholds);
  std::memcpy(synth.coverageParts.mapped(), &uniform, sizeof(uniform));
}

CrowdSynth makeCrowdSynth(const gpu::Context& context, const anim::MotionPair& pair,
                          const crowd::Crowd& crowd, const MotionCacheOptions& cache,
                          const LodOptions& lod) {
  CrowdSynth synth;
  synth.pair = &pair;
  synth.motion = uploadMotionPair(context, pair);
  synth.crowd = crowd::uploadCrowd(context, crowd);
  synth.steering = crowd.steering;
  VkDeviceSize bytes = VkDeviceSize(crowd.size()) * pair.jointCount() * sizeof(JointMatrix);
  synth.joints = gpu::Buffer(context, bytes, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  synth.cache = makeGpuMotionCache(context, pair, cache);
  if (lod.enabled) {
    if (!lod.skeleton) fail("LOD needs the skeleton to find the body parts");
    synth.lod = true;
    synth.coverageParts =
        gpu::Buffer(context, sizeof(CoverageParts), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                    gpu::MemoryUse::HostVisible);
    setLodThresholds(synth, *lod.skeleton, lod.thresholds);
    std::vector<CoverageMask> none(std::max<size_t>(crowd.size(), 1), CoverageMask{});
    synth.masks = gpu::makeStorageBuffer<CoverageMask>(context, none);
  }
  if (cache.enabled) {
    // At most one chunk per character, so the counts never outgrow their buffers.
    VkDeviceSize n = std::max<VkDeviceSize>(crowd.size(), 1);
    std::vector<uint32_t> inJoints(n, gpu_types::kPoseInJoints);
    synth.poseSource = gpu::makeStorageBuffer<uint32_t>(context, inJoints);
    synth.characterLists =
        gpu::Buffer(context, n * 4, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
    synth.listCounts = gpu::Buffer(context, n * 4, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
    synth.dispatchArgs =
        gpu::Buffer(context, n * 12, gpu::kStorageUsage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                    gpu::MemoryUse::DeviceLocal);
  }
  return synth;
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

void recordSynthesis(VkCommandBuffer cmd, const SynthPrograms& programs, const CrowdSynth& synth,
                     float dt, VkDeviceSize maxBindingBytes, const anim::SpeedRetarget& retarget,
                     const CoverageCamera* lodCamera) {
  RootMotionJob root{&synth.motion, synth.pair, &synth.crowd, dt, synth.steering, retarget};
  root.record(cmd, programs);
  gpu::computeToComputeBarrier(cmd);
  const bool lod = synth.lod && lodCamera;
  if (lod) {
    // Sphere centres estimated from placement and the clip's mean pose: no dependency on
    // this frame's pose pass, which the masks then trim.
    CoverageJob coverage{&synth.crowd, &synth.coverageParts, nullptr,           &synth.masks,
                         nullptr,      *lodCamera,           synth.jointCount()};
    coverage.record(cmd, programs.coverage);
    gpu::computeToComputeBarrier(cmd);
  }
  const bool cached = synth.cache.options.enabled;
  const VkDeviceSize perCharacter = VkDeviceSize(synth.jointCount()) * sizeof(JointMatrix);
  // Also bounded by 65535 workgroups of 64 per dispatch.
  const uint32_t chunk =
      static_cast<uint32_t>(std::min<VkDeviceSize>(maxBindingBytes / perCharacter, 65535u * 64u));
  const uint32_t chunks = (synth.crowd.count + chunk - 1) / chunk;
  if (cached) {
    CacheJob{&synth.motion, &synth.crowd, &synth.cache}.record(cmd, programs);
    vkCmdFillBuffer(cmd, synth.listCounts.get(), 0, VkDeviceSize(chunks) * 4, 0u);
    gpu::computeToComputeBarrier(cmd);
    for (uint32_t c = 0; c < chunks; ++c) {
      uint32_t first = c * chunk;
      CachePush push{};
      push.characterCount = std::min(chunk, synth.crowd.count - first);
      push.rowCount = synth.cache.rowCount;
      push.bucketWidth = synth.cache.options.bucketWidth;
      push.firstCharacter = first;
      push.chunk = c;
      push.jointCount = synth.jointCount();
      gpu::Binding bindings[] = {gpu::storageBinding(0, synth.crowd.motion),
                                 gpu::storageBinding(3, synth.cache.bucketSlot),
                                 gpu::storageBinding(6, synth.characterLists),
                                 gpu::storageBinding(7, synth.listCounts),
                                 gpu::storageBinding(9, synth.poseSource)};
      gpu::dispatch(cmd, programs.cacheClassify, bindings, push, push.characterCount);
    }
    gpu::computeToComputeBarrier(cmd);
    gpu::Binding argBindings[] = {gpu::storageBinding(7, synth.listCounts),
                                  gpu::storageBinding(8, synth.dispatchArgs)};
    gpu::dispatch(cmd, programs.cacheArgs, argBindings, chunks, chunks);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                       VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT);
  }
  for (uint32_t c = 0; c < chunks; ++c) {
    uint32_t first = c * chunk;
    PoseJob pose{&synth.motion,
                 &synth.crowd,
                 &synth.joints,
                 first,
                 std::min(chunk, synth.crowd.count - first),
                 VkDeviceSize(first) * perCharacter};
    pose.masks = lod ? &synth.masks : nullptr;
    if (!cached) {
      pose.record(cmd, programs);
      continue;
    }
    pose.characterList = &synth.characterLists;
    pose.listCounts = &synth.listCounts;
    pose.dispatchArgs = &synth.dispatchArgs;
    pose.listBase = first;  // the characters whose bucket is not resident
    pose.countIndex = c;
    pose.argsOffset = VkDeviceSize(c) * 12;
    pose.record(cmd, programs);
  }
  // The cache counters are read on the host after the frame.
  if (cached)
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
}

void recordMaterializeCachedPoses(VkCommandBuffer cmd, const SynthPrograms& programs,
                                  const CrowdSynth& synth, VkDeviceSize maxBindingBytes) {
  if (!synth.cache.options.enabled) return;
  const VkDeviceSize perCharacter = VkDeviceSize(synth.jointCount()) * sizeof(JointMatrix);
  const uint32_t chunk =
      static_cast<uint32_t>(std::min<VkDeviceSize>(maxBindingBytes / perCharacter, 65535u * 64u));
  for (uint32_t first = 0; first < synth.crowd.count; first += chunk) {
    MaterializeCachedJob job{&synth.crowd,
                             &synth.cache,
                             &synth.poseSource,
                             &synth.joints,
                             first,
                             std::min(chunk, synth.crowd.count - first),
                             VkDeviceSize(first) * perCharacter,
                             synth.lod ? &synth.masks : nullptr};
    job.record(cmd, programs);
  }
  gpu::computeToComputeBarrier(cmd);
}

}  // namespace throng::synth
