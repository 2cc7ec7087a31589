#pragma once
// The frame orchestrator for synthesis: owns the GPU copies of one motion pair, the crowd's
// state and the joint-matrix output, and records the passes in order with their barriers.
#include "anim/motion_texture.h"
#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "synth/coverage.h"
#include "synth/motion_cache.h"
#include "synth/motion_gpu.h"
#include "synth/synth_jobs.h"

namespace throng::synth {

// Pixel-coverage LOD: per-character joint masks from the camera, thresholds in pixels.
struct LodOptions {
  bool enabled = false;
  CoverageThresholds thresholds;
  const anim::Skeleton* skeleton = nullptr;  // joint names find the body parts
};

struct CrowdSynth {
  const anim::MotionPair* pair = nullptr;
  GpuMotionPair motion;
  crowd::CrowdBuffers crowd;
  gpu::Buffer joints;  // crowd.count × jointCount JointMatrix
  GpuMotionCache cache;
  // With the cache on: per character, where its joint matrices come from (kPoseInJoints or
  // its cache entry; the renderer composes cached ones), and per pose chunk the list of
  // characters that the full pose pass synthesizes.
  gpu::Buffer poseSource;      // uint per character
  gpu::Buffer characterLists;  // crowd.count: chunk c's uncached characters from its first one
  gpu::Buffer listCounts;      // one per chunk
  gpu::Buffer dispatchArgs;    // a VkDispatchIndirectCommand per chunk
  // With LOD on: the body parts and thresholds (uniform) and each character's mask.
  bool lod = false;
  gpu::Buffer coverageParts;
  gpu::Buffer masks;
  anim::Steering steering = anim::Steering::KeepHeading;

  uint32_t jointCount() const { return motion.jointCount; }
};

CrowdSynth makeCrowdSynth(const gpu::Context& context, const anim::MotionPair& pair, const crowd::Crowd& crowd,
                          const MotionCacheOptions& cache = {}, const LodOptions& lod = {});
// New thresholds for a running synthesis (call between frames, with no frame in flight).
void setLodThresholds(CrowdSynth& synth, const anim::Skeleton& skeleton, const CoverageThresholds& thresholds);

// Root motion, the motion cache when enabled, then the pose pass in chunks that each bind at most `maxBindingBytes` of output.
// With LOD on and `lodCamera` given, the coverage pass sets each character's mask first.
void recordSynthesis(VkCommandBuffer cmd, const SynthPrograms& programs, const CrowdSynth& synth, float dt,
                     VkDeviceSize maxBindingBytes, const anim::SpeedRetarget& retarget = {},
                     const CoverageCamera* lodCamera = nullptr);

// With the cache on, cached characters' joints are not in `joints` after recordSynthesis (the
// renderer composes them): this writes them there too, for consumers that read `joints`.
void recordMaterializeCachedPoses(VkCommandBuffer cmd, const SynthPrograms& programs, const CrowdSynth& synth,
                                  VkDeviceSize maxBindingBytes);

// Speed changes every `period` seconds (paper: 5 s): tells each step whether it starts a new
// epoch, and the speed range and buckets the new targets are drawn from.
struct SpeedSchedule {
  float period = 0.0f;  // 0: speeds never change
  uint32_t seed = 1;
  float lo = 0.0f, hi = 1.0f;
  float bucketWidth = 0.0f;
  double time = 0.0;
  // Advances the clock by dt; the retarget to pass to this step's root motion.
  anim::SpeedRetarget advance(float dt);
};

}  // namespace throng::synth
