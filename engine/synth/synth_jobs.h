#pragma once
// The synthesis passes as jobs (ozz style): public named inputs and outputs, validate() that
// lists what is missing or inconsistent, record() that checks and records the dispatch.
#include <string>
#include <vector>

#include "anim/motion_texture.h"
#include "anim/reference_synth.h"
#include "crowd/crowd.h"
#include "gpu/program.h"
#include "synth/coverage.h"
#include "synth/motion_cache.h"
#include "synth/motion_gpu.h"
#include "synth/update_rate.h"

namespace throng::synth {

// The compiled programs of the synthesis passes. The pose pass is specialized for one
// skeleton (joint count and parent array are baked in), so build one per skeleton topology.
struct SynthPrograms {
  gpu::ComputeProgram rootMotion;
  gpu::ComputeProgram rootMotionCoverage;  // root motion that does the frame's coverage too
  gpu::ComputeProgram rootMotionPrep;      // before root motion: steering and new target speeds
  gpu::ComputeProgram pose;
  gpu::ComputeProgram poseMasked;  // the same with the coverage-LOD joint masks
  gpu::ComputeProgram cacheInsert;
  gpu::ComputeProgram cacheFill;  // specialized like `pose`
  gpu::ComputeProgram cacheClassify;
  gpu::ComputeProgram cacheArgs;
  gpu::ComputeProgram poseCached;  // materializes A = M · cached pose (specialized: joint count)
  gpu::ComputeProgram coverage;    // pixel-coverage LOD (coverage.h)
  // The passes over every group of a crowd at once (group_passes.h): root motion without and
  // with the coverage, the coverage alone, the cache insert and the cache classify.
  gpu::ComputeProgram rootMotionGroups;
  gpu::ComputeProgram rootMotionGroupsCoverage;
  gpu::ComputeProgram coverageGroups;  // the coverage alone (frames with walls)
  gpu::ComputeProgram cacheInsertGroups;
  gpu::ComputeProgram cacheClassifyGroups;
  gpu::Buffer noList;                     // bindings for a pose pass over a plain range
  gpu::Buffer noParts;                    // the cache fill's CoverageParts without far bodies
  std::vector<int32_t> poseParents;       // the skeleton `pose` was specialized for
  std::vector<bool> poseAnimatedOffsets;  // and which joints' offsets it reads per frame
  bool poseTexelsInUniform = false;       // and where it reads the texels (motion_gpu.h)
  std::vector<uint32_t> specialization;   // everything baked in (skeleton, fixed bones, texels)
  SynthPrograms(const gpu::Context& context, const anim::MotionPair& pair);
  // Whether these programs serve `pair` too (the same values baked in).
  bool fits(const gpu::Context& context, const anim::MotionPair& pair) const;
};

// Eq. 10 on the GPU; twin: anim::stepCharacter.
struct RootMotionJob {
  const GpuMotionPair* motion = nullptr;       // input
  const anim::MotionPair* clips = nullptr;     // input: cycle durations and travel
  const crowd::CrowdBuffers* crowd = nullptr;  // input and output (updated in place)
  uint32_t firstCharacter = 0;                 // the group [first, first + count)
  uint32_t characterCount = 0;                 // 0: every character from firstCharacter
  float dt = 0.0f;
  anim::Steering steering = anim::Steering::KeepHeading;
  anim::SpeedRetarget retarget;  // speed changes over time (epoch 0: none)
  // Optional output: with an enabled cache, each character's bucket is flagged as requested
  // (the cache's lookup step, before CacheJob's insert and fill).
  const GpuMotionCache* cache = nullptr;
  // Optional: the frame's coverage LOD pass done in the same pass (CoverageJob without areas)
  // for the characters just moved: each one's mask in `masks` from the group's `coverageParts`
  // seen by the camera in `coverageView` (this frame's, written before the pass).
  const gpu::Buffer* coverageView = nullptr;   // input: uniform CoverageView
  const gpu::Buffer* coverageParts = nullptr;  // input: uniform CoverageParts
  const gpu::Buffer* masks = nullptr;          // input/output: CoverageMask per character
  // Optional, with the coverage: the update-rate LOD (update_rate.h). Only the chunks that
  // UpdateScheduleJob listed this step move, each by its elapsed steps, dispatched by the
  // schedule's count with `scheduledProgram` (makeScheduledRootMotionProgram); chunks count from
  // firstCharacter. Twin: synth::stepScheduledCpu.
  const GpuUpdateRate* updateRate = nullptr;
  const gpu::ComputeProgram* scheduledProgram = nullptr;

  std::vector<std::string> validate() const;
  // Records root_motion_prep.comp first (and a barrier) when the step steers or retargets.
  void record(VkCommandBuffer cmd, const SynthPrograms& programs) const;
};

// root_motion_scheduled.comp specialized for `pair` like SynthPrograms' root motion.
gpu::ComputeProgram makeScheduledRootMotionProgram(const gpu::Context& context,
                                                   const anim::MotionPair& pair);

// root_motion_prep.comp over characters [first, first + count) when the step steers or draws
// new target speeds; false (nothing recorded) otherwise. The caller orders root motion after it.
bool recordRootMotionPrep(VkCommandBuffer cmd, const SynthPrograms& programs,
                          const crowd::CrowdBuffers& crowd, uint32_t first, uint32_t count,
                          anim::Steering steering, const anim::SpeedRetarget& retarget);

// Blend + hierarchy + joint points on the GPU; twin: anim::poseCharacter.
struct PoseJob {
  const GpuMotionPair* motion = nullptr;       // input
  const crowd::CrowdBuffers* crowd = nullptr;  // input
  const gpu::Buffer* joints = nullptr;         // output: JointPoint per character per joint
  uint32_t firstCharacter = 0;                 // the chunk [first, first + count)
  uint32_t characterCount = 0;                 // 0: every character from firstCharacter
  VkDeviceSize jointsOffset = 0;               // where the chunk's output starts in `joints`
  // Optional: pose only the chunk-local characters listed at characterList[listBase …] (their
  // number at listCounts[countIndex], the group count at dispatchArgs[argsOffset]).
  const gpu::Buffer* characterList = nullptr;
  const gpu::Buffer* listCounts = nullptr;
  const gpu::Buffer* dispatchArgs = nullptr;
  uint32_t listBase = 0, countIndex = 0;
  VkDeviceSize argsOffset = 0;
  const gpu::Buffer* masks = nullptr;  // optional input: CoverageMask per character (LOD)

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const SynthPrograms& programs) const;
};

// The joint points of the cached characters of a chunk written into `joints` (M · p from their
// poseSource entry). The frame does not need it: the renderer places the same points itself;
// tests and exports that want every joint in one buffer do. Twin: MotionCacheCpu::pose.
struct MaterializeCachedJob {
  const crowd::CrowdBuffers* crowd = nullptr;  // input: placement and scale
  const GpuMotionCache* cache = nullptr;       // input: the cached poses' layout
  const gpu::Buffer* cacheData = nullptr;      // input: the cached poses (makeCacheData)
  const gpu::Buffer* poseSource = nullptr;     // input: per character, from the cache classify pass
  const gpu::Buffer* joints = nullptr;         // output: JointPoint per character per joint
  uint32_t firstCharacter = 0, characterCount = 0;
  VkDeviceSize jointsOffset = 0;
  const gpu::Buffer* masks = nullptr;  // optional: only the joints the LOD mask keeps

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const SynthPrograms& programs) const;
};

// The motion cache for this frame, after root motion flagged every character's bucket (the
// lookup): insert (FIFO, once per bucket) and fill (synthesize fresh entries); then the classify
// pass points cached characters at it. CPU twin: MotionCacheCpu::update.
// Over one group of characters: its clip set's cache, its entries in the shared data buffer.
struct CacheJob {
  const GpuMotionPair* motion = nullptr;       // input
  const crowd::CrowdBuffers* crowd = nullptr;  // input: the crowd the group's range is in
  const GpuMotionCache* cache = nullptr;       // input and output
  const gpu::Buffer* data = nullptr;           // output: the entries, from cache->dataBase
  uint32_t firstCharacter = 0;                 // the group [first, first + count)
  uint32_t characterCount = 0;                 // 0: every character from firstCharacter
  // Optional, both or neither (far bodies drawn: the LOD on): the fill also writes each fresh
  // pose's FarBodyPose, of the joints the group's CoverageParts name.
  const gpu::Buffer* parts = nullptr;         // input: uniform CoverageParts
  const gpu::Buffer* farBodyPoses = nullptr;  // output: makeFarBodyPoses over `data`

  std::vector<std::string> validate() const;
  // The steps after the lookup (done by RootMotionJob with `cache` set), one by one so that a
  // crowd's groups share each barrier: insert, barrier (compute and indirect), fill, barrier.
  void recordInsert(VkCommandBuffer cmd, const SynthPrograms& programs) const;
  void recordFill(VkCommandBuffer cmd, const SynthPrograms& programs) const;
};

}  // namespace throng::synth
