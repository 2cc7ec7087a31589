#include "synth/crowd_synth.h"

#include <algorithm>
#include <cmath>

#include "gpu/commands.h"
#include "synth/gpu_types.h"

namespace throng::synth {

CrowdSynth makeCrowdSynth(const gpu::Context& context, const anim::MotionPair& pair, const crowd::Crowd& crowd,
                          const MotionCacheOptions& cache) {
  CrowdSynth synth;
  synth.pair = &pair;
  synth.motion = uploadMotionPair(context, pair);
  synth.crowd = crowd::uploadCrowd(context, crowd);
  synth.steering = crowd.steering;
  VkDeviceSize bytes = VkDeviceSize(crowd.size()) * pair.jointCount() * sizeof(JointMatrix);
  synth.joints = gpu::Buffer(context, bytes, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  synth.cache = makeGpuMotionCache(context, pair, cache);
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

void recordSynthesis(VkCommandBuffer cmd, const SynthPrograms& programs, const CrowdSynth& synth, float dt,
                     VkDeviceSize maxBindingBytes, const anim::SpeedRetarget& retarget) {
  RootMotionJob root{&synth.motion, synth.pair, &synth.crowd, dt, synth.steering, retarget};
  root.record(cmd, programs);
  gpu::computeToComputeBarrier(cmd);
  const bool cached = synth.cache.options.enabled;
  if (cached) CacheJob{&synth.motion, &synth.crowd, &synth.cache}.record(cmd, programs);
  const VkDeviceSize perCharacter = VkDeviceSize(synth.jointCount()) * sizeof(JointMatrix);
  // Also bounded by 65535 workgroups of 64 per dispatch.
  const uint32_t chunk = static_cast<uint32_t>(std::min<VkDeviceSize>(maxBindingBytes / perCharacter, 65535u * 64u));
  for (uint32_t first = 0; first < synth.crowd.count; first += chunk) {
    PoseJob pose{&synth.motion, &synth.crowd, &synth.joints, first, std::min(chunk, synth.crowd.count - first),
                 VkDeviceSize(first) * perCharacter, cached ? &synth.cache : nullptr};
    pose.record(cmd, programs);
  }
  // The cache counters are read on the host after the frame.
  if (cached) gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_HOST_BIT);
}

}  // namespace throng::synth
