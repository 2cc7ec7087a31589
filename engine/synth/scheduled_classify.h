#pragma once
// The motion cache's classify under the update-rate LOD (shaders/update_rate.h,
// ClassifySchedulePush): only the characters of the chunks that moved this step get a new pose
// source. A character that stood still has the phase and speed it had, so its pose source still
// names the right cache row, or, when it was not cached, the pose pass's joints for it are still
// its pose. The one thing that could change under it is the cache itself: an entry filled this
// step may have evicted the bucket a still character's pose source names, so a step whose insert
// filled any entry classifies every chunk (on the GPU, without a readback:
// cache_classify_args.comp). Once every bucket in use is resident that never happens.
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "gpu/program.h"
#include "shaders/update_rate.h"
#include "synth/motion_cache.h"
#include "synth/update_rate.h"

namespace throng::synth {

using gpu_types::ClassifySchedulePush;
using gpu_types::ScheduledClassifyArgs;
static_assert(sizeof(ClassifySchedulePush) == 32, "ClassifySchedulePush must match the GLSL block");
static_assert(sizeof(ScheduledClassifyArgs) == 16, "ScheduledClassifyArgs must match the GLSL");

// The two passes and the arguments buffer between them.
struct ScheduledClassify {
  gpu::ComputeProgram args;      // cache_classify_args.comp
  gpu::ComputeProgram classify;  // cache_classify_scheduled.comp, a workgroup per chunk
  gpu::Buffer dispatchArgs;      // ScheduledClassifyArgs (storage and indirect)
};
// For a schedule of `chunkCount` chunks; throws LimitError when the device cannot dispatch a
// workgroup per chunk.
ScheduledClassify makeScheduledClassify(const gpu::Context& context, uint32_t chunkCount);

// cache_classify_args.comp then cache_classify_scheduled.comp as a job; twin:
// classifyScheduledCpu. Needs the step's schedule (its list and dispatch) and the cache's insert
// (its fresh slots) recorded before it, and the pose lists' counts zeroed.
struct ScheduledClassifyJob {
  const crowd::CrowdBuffers* crowd = nullptr;   // input: motion texels
  const GpuMotionCache* cache = nullptr;        // inputs: bucketSlot, freshSlots
  const GpuUpdateRate* rate = nullptr;          // inputs: chunkList, dispatchArgs
  const gpu::Buffer* dispatchArgs = nullptr;    // output: ScheduledClassifyArgs
  const gpu::Buffer* poseSource = nullptr;      // output: uint per character (listed chunks')
  const gpu::Buffer* characterLists = nullptr;  // output: misses, from each pose chunk's first
  const gpu::Buffer* listCounts = nullptr;      // output: misses per pose chunk (added to)
  uint32_t characterCount = 0;                  // the crowd's, one clip set
  uint32_t poseChunk = 0;                       // characters per pose chunk
  uint32_t jointCount = 0;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const ScheduledClassify& programs) const;
};

// CPU twin of cache_classify_args.comp and cache_classify_scheduled.comp: whether every chunk is
// classified (the insert filled `freshSlots` entries), then for the characters of those chunks
// (or of `movedChunks`) their pose source from the cache's `bucketSlot`, each miss appended to
// its pose chunk's list in `misses` (one list per pose chunk, in character order; the GPU's order
// varies). Other characters keep their pose source. Returns whether every chunk was classified.
bool classifyScheduledCpu(std::span<const uint32_t> movedChunks, uint32_t freshSlots,
                          std::span<const glm::vec4> motion, std::span<const int32_t> bucketSlot,
                          const ClassifySchedulePush& push, std::span<uint32_t> poseSource,
                          std::vector<std::vector<uint32_t>>& misses);

}  // namespace throng::synth
