#pragma once
// A crowd of several clip sets synthesized with one dispatch per pass where a pass does not
// depend on the clip set's specialization: root motion (with the cache's lookup and the
// coverage LOD) and the cache's classify pass. Each character finds its group in a small
// uniform table (at most kSynthMaxGroups); the clips' root rows, the caches' request flags and
// bucket slots of every group live in shared buffers at per-group offsets. Why: on lavapipe a
// dispatch of more than one workgroup hands its work to the worker threads, tens of
// microseconds at a few thousand characters, so four clip sets in four dispatches per pass
// cost about twice one (docs/performance.md, the clip-set row).
#include <span>
#include <vector>

#include "anim/motion_texture.h"
#include "anim/root_motion.h"
#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "synth/coverage.h"
#include "synth/motion_cache.h"
#include "synth/synth_jobs.h"

namespace throng::synth {

// One group as the shared buffers describe it.
struct GroupDescription {
  const anim::MotionPair* pair = nullptr;
  const GpuMotionCache* cache = nullptr;  // its cache (a disabled one when the cache is off)
  uint32_t first = 0;                     // its first character; groups in ascending order
  anim::Steering steering = anim::Steering::KeepHeading;
};

struct SynthGroupBuffers {
  uint32_t groupCount = 0;
  std::vector<uint32_t> firsts;           // each group's first character
  std::vector<anim::Steering> steerings;  // and its steering (root_motion_prep.comp)
  gpu::Buffer table;                      // uniform SynthGroupTable
  gpu::Buffer rootRows;       // each group's slow then fast clip root rows, a vec4 per frame
  gpu::Buffer coverageParts;  // LOD on: uniform CoverageParts[kSynthMaxGroups], host-visible
  gpu::Buffer requested;      // cache on: each group's request flags (uint) from its bucket base
  gpu::Buffer bucketSlot;     // cache on: each group's bucket slots (int) from its bucket base
};

// Throws Error for no group, more than kSynthMaxGroups or groups out of order.
SynthGroupBuffers makeSynthGroupBuffers(const gpu::Context& context,
                                        std::span<const GroupDescription> groups, bool lod,
                                        bool cached);
void writeGroupCoverageParts(const SynthGroupBuffers& buffers, uint32_t group,
                             const CoverageParts& parts);

// RootMotionJob over every group at once; twin: anim::stepCharacter with each character's
// group's pair.
struct GroupRootMotionJob {
  const SynthGroupBuffers* groups = nullptr;   // input: the table, root rows (and parts)
  const crowd::CrowdBuffers* crowd = nullptr;  // input and output (updated in place)
  float dt = 0.0f;
  anim::SpeedRetarget retarget;
  // Optional: with an enabled cache (every group's has the same options), each character's
  // bucket is flagged in groups->requested.
  const MotionCacheOptions* cache = nullptr;
  uint32_t bucketCount = 0;
  // Optional: the frame's coverage in the same pass, as RootMotionJob.
  const gpu::Buffer* coverageView = nullptr;  // input: uniform CoverageView
  const gpu::Buffer* masks = nullptr;         // input/output: CoverageMask per character

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const SynthPrograms& programs) const;
};

// The frame's coverage LOD pass (CoverageJob without areas) of every group in one dispatch, for
// frames that move characters between root motion and coverage (walls); the same masks as
// GroupRootMotionJob's coverage. Twin: synth::coverageCharacter with each group's parts.
struct GroupCoverageJob {
  const SynthGroupBuffers* groups = nullptr;   // input: the table and every group's parts
  const crowd::CrowdBuffers* crowd = nullptr;  // input: placement and motion (texel views)
  const gpu::Buffer* coverageView = nullptr;   // input: uniform CoverageView, this frame's
  const gpu::Buffer* masks = nullptr;          // input/output: CoverageMask per character

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const SynthPrograms& programs) const;
};

// The motion cache's insert step of every group in one dispatch: each group's FIFO on its own
// cache (counters, slots, fresh slots and fill arguments) and the shared request flags and
// bucket slots; then each group's CacheJob::recordFill as before. Twin: MotionCacheCpu::update.
struct GroupInsertJob {
  const SynthGroupBuffers* groups = nullptr;  // input/output: shared flags and slots
  std::vector<const GpuMotionCache*> caches;  // input/output: one per group

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const SynthPrograms& programs) const;
};

// The cache classify pass over every group at once: pose chunks of chunkSize characters,
// numbered across groups (group g's first chunk is firstChunk[g]); twin: as the per-group pass.
struct GroupClassifyJob {
  const SynthGroupBuffers* groups = nullptr;    // input: the table, bucketSlot
  const crowd::CrowdBuffers* crowd = nullptr;   // input
  const gpu::Buffer* characterLists = nullptr;  // output: each chunk's uncached characters
  const gpu::Buffer* listCounts = nullptr;      // output: their number per chunk (zeroed before)
  const gpu::Buffer* poseSource = nullptr;      // output: per character
  uint32_t chunkSize = 0, jointCount = 0, bucketCount = 0;
  float bucketWidth = 0.0f;
  std::vector<uint32_t> firstChunk;  // per group

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const SynthPrograms& programs) const;
};

}  // namespace throng::synth
