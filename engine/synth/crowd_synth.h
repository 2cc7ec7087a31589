#pragma once
// The frame orchestrator for synthesis: owns the crowd's per-character state and joint-point
// output for every character and, per group of characters (clip set), the GPU copies of its
// motion pair and its cache; records the passes in order, each over every group's range.
#include <optional>
#include <span>
#include <vector>

#include "anim/motion_texture.h"
#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "gpu/timestamps.h"
#include "synth/coverage.h"
#include "synth/group_passes.h"
#include "synth/motion_cache.h"
#include "synth/motion_gpu.h"
#include "synth/scheduled_classify.h"
#include "synth/synth_jobs.h"
#include "synth/update_rate.h"

namespace throng::synth {

// Pixel-coverage LOD: per-character joint masks from the camera, thresholds in pixels.
struct LodOptions {
  bool enabled = false;
  CoverageThresholds thresholds;
  const anim::Skeleton* skeleton = nullptr;  // joint names find the body parts
  // Update-rate LOD (update_rate.h): > 0, far characters move every few steps, drawn at most
  // this many pixels from where moving them every step would draw them. Needs LOD and a crowd
  // of one clip set; applies to the frames whose root motion does the coverage (no walls).
  float updateLagPixels = 0.0f;
};

// One clip set of a crowd: the characters [first, first + count) of the crowd's buffers,
// animated by one motion pair, with the pair's own cache (its entries in the shared data buffer)
// and body parts for the coverage LOD.
struct SynthGroup {
  const anim::MotionPair* pair = nullptr;
  GpuMotionPair motion;
  GpuMotionCache cache;
  gpu::Buffer coverageParts;  // LOD on: uniform CoverageParts of this pair
  anim::Steering steering = anim::Steering::KeepHeading;
  uint32_t first = 0, count = 0;
};

// A crowd's synthesis state: ONE set of per-character buffers for every character, whatever
// clip set animates it, so that each synthesis pass runs on a group's sub-range in place and
// the renderer draws the whole crowd from one set of buffers (cached characters stay cached).
struct CrowdSynth {
  crowd::CrowdBuffers crowd;  // every character's placement and motion
  gpu::Buffer joints;         // crowd.count × jointCount JointPoint
  // With the cache on: per character, where its joint points come from (kPoseInJoints or
  // its entry in cacheData; the renderer composes cached ones), and per pose chunk the list of
  // characters that the full pose pass synthesizes.
  gpu::Buffer poseSource;      // uint per character
  gpu::Buffer characterLists;  // crowd.count: chunk c's uncached characters from its first one
  gpu::Buffer listCounts;      // one per chunk
  gpu::Buffer dispatchArgs;    // a VkDispatchIndirectCommand per chunk
  gpu::Buffer cacheData;       // every group's cache entries (makeCacheData)
  gpu::Buffer farBodyPoses;    // with LOD and cache: the far bodies' table (makeFarBodyPoses)
  // With LOD on: each character's mask, and the frame's camera for the root motion pass that
  // does the coverage too (written at the start of the frame's root motion).
  bool lod = false;
  gpu::Buffer masks;
  gpu::Buffer coverageView;  // uniform CoverageView
  // With the update-rate LOD: the chunks' schedule and the root motion it dispatches.
  std::optional<GpuUpdateRate> updateRate;
  gpu::ComputeProgram scheduledRootMotion;
  // With the motion cache too: its classify over the moved chunks (scheduled_classify.h).
  std::optional<ScheduledClassify> scheduledClassify;
  std::vector<SynthGroup> groups;  // contiguous ranges, in order, covering every character
  // With several groups: root motion and the cache classify run over all of them in one
  // dispatch each, from these shared buffers (group_passes.h).
  SynthGroupBuffers shared;
  bool sharedPasses() const { return groups.size() > 1; }

  const SynthGroup& front() const { return groups.front(); }
  uint32_t jointCount() const { return front().motion.jointCount; }
  bool cached() const { return front().cache.options.enabled; }
};

// One group per pair: pair k animates the characters [groupFirst[k], groupFirst[k + 1]) of
// `crowd` (groupFirst has pairs.size() + 1 entries from 0 to crowd.size()), at most
// kSynthMaxGroups pairs. Every pair needs the same joint count. The cache budget is per clip
// set: a crowd of k sets has k times the budget, shared by clipSetBudgets. Throws Error otherwise.
CrowdSynth makeCrowdSynth(const gpu::Context& context,
                          std::span<const anim::MotionPair* const> pairs,
                          std::span<const uint32_t> groupFirst, const crowd::Crowd& crowd,
                          const MotionCacheOptions& cache = {}, const LodOptions& lod = {});
// The budgets of a crowd's clip set caches: k sets share k × `budget` bytes, max-min fair by
// what each needs to hold all its buckets (an entry's size grows with the clip's cycle), so a
// set of short cycles leaves what it does not need to one of long cycles. A single set gets
// `budget`. needBytes[k]: set k's bucket count × entry bytes.
std::vector<uint64_t> clipSetBudgets(std::span<const uint64_t> needBytes, uint64_t budget);
// One group: every character animated by `pair`.
CrowdSynth makeCrowdSynth(const gpu::Context& context, const anim::MotionPair& pair,
                          const crowd::Crowd& crowd, const MotionCacheOptions& cache = {},
                          const LodOptions& lod = {});
// New thresholds for a running synthesis (call between frames, with no frame in flight).
void setLodThresholds(CrowdSynth& synth, const anim::Skeleton& skeleton,
                      const CoverageThresholds& thresholds);
// The cache counters summed over the groups.
MotionCacheStats readCacheStats(const CrowdSynth& synth);

// Root motion, the motion cache when enabled, then the pose pass in chunks that each bind at
// most `maxBindingBytes` of output; each pass runs over every group's range with the group's
// programs (programs[k] for group k: the pose pass is specialized per skeleton and pair).
// With LOD on and `lodCamera` given, the coverage pass sets each character's mask first.
void recordSynthesis(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                     const CrowdSynth& synth, float dt, VkDeviceSize maxBindingBytes,
                     const anim::SpeedRetarget& retarget = {},
                     const CoverageCamera* lodCamera = nullptr);
// The two halves of recordSynthesis, for a frame that puts work between them (constraints on
// where root motion moved the characters, e.g. walls): root motion of every group (with the
// cache on, also the cache's lookup step), then a barrier; then coverage, the rest of the motion
// cache and pose. recordPosePasses needs recordRootMotionPasses before it in the same frame,
// except before a crowd's first frame (scene::FramePreparation): nothing has asked the cache for
// a bucket yet, so its insert does nothing and every character is posed.
// With LOD on and `lodCamera` given to recordRootMotionPasses, root motion also does the
// coverage pass (one pass fewer) and returns true: pass that on as `coverageDone`. Give it no
// camera when work between the halves moves characters.
bool recordRootMotionPasses(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                            const CrowdSynth& synth, float dt,
                            const anim::SpeedRetarget& retarget = {},
                            const CoverageCamera* lodCamera = nullptr);
void recordPosePasses(VkCommandBuffer cmd, std::span<const SynthPrograms* const> programs,
                      const CrowdSynth& synth, VkDeviceSize maxBindingBytes,
                      const CoverageCamera* lodCamera = nullptr,
                      gpu::TimestampPool* passMarks = nullptr, bool coverageDone = false);
// With `passMarks`, recordPosePasses writes three timestamps, after the coverage pass, after the
// motion cache's passes and after the pose pass (each whether or not the pass ran), so a bench
// can say where a frame's synthesis goes.
constexpr uint32_t kPosePassMarks = 3;
// The same for a crowd of one group.
void recordSynthesis(VkCommandBuffer cmd, const SynthPrograms& programs, const CrowdSynth& synth,
                     float dt, VkDeviceSize maxBindingBytes,
                     const anim::SpeedRetarget& retarget = {},
                     const CoverageCamera* lodCamera = nullptr);

// With the cache on, cached characters' joints are not in `joints` after recordSynthesis (the
// renderer composes them): this writes them there too, for consumers that read `joints`.
void recordMaterializeCachedPoses(VkCommandBuffer cmd,
                                  std::span<const SynthPrograms* const> programs,
                                  const CrowdSynth& synth, VkDeviceSize maxBindingBytes);
void recordMaterializeCachedPoses(VkCommandBuffer cmd, const SynthPrograms& programs,
                                  const CrowdSynth& synth, VkDeviceSize maxBindingBytes);

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
