#pragma once
// The motion cache of DESIGN §3.4, resident on the GPU: key = speed weight quantized to a
// bucket, data = the synthesized character-space clip at that speed (one pose per segment of
// the slow/fast frame grid, all joints). Lookup before synthesis, a miss synthesizes and
// inserts, FIFO eviction of the oldest entry when the byte budget is full. A character whose
// bucket is resident does no blending and no hierarchy: A = M · cached pose.
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/motion_texture.h"
#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "gpu/program.h"
#include "synth/motion_gpu.h"

namespace throng::synth {

struct MotionCacheOptions {
  bool enabled = false;
  float bucketWidth = 0.05f;               // in speed-weight units (w ∈ [0, 1])
  uint64_t budgetBytes = 20ull << 20;      // paper: 20 MB
};

struct MotionCacheStats {
  uint32_t hits = 0, misses = 0, evictions = 0, entries = 0;
  uint64_t bytesUsed = 0, budgetBytes = 0;
};

uint32_t speedBucketCount(float bucketWidth);
uint32_t speedBucket(float w, float bucketWidth, uint32_t bucketCount);
float bucketSpeed(uint32_t bucket, float bucketWidth);
// w rounded to its bucket's speed (what the cached pose is synthesized at).
float quantizeSpeed(float w, float bucketWidth);

// Segment k = slow frame + fast frame; each (slow, fast) frame pair met while the phase sweeps
// one cycle has its own k. Unused k hold (-1, -1).
std::vector<glm::ivec2> cacheSegments(int slowFrames, int fastFrames);

// Throws Error on a bucket width outside (0, 1] or an entry larger than the budget allows at 0.
void validateCacheOptions(const MotionCacheOptions& options);

struct GpuMotionCache {
  MotionCacheOptions options;
  uint32_t bucketCount = 0, segmentCount = 0, capacity = 0, jointCount = 0;
  uint64_t entryBytes = 0;
  gpu::Buffer counters;       // CacheCounters, host-visible (read back every frame)
  gpu::Buffer requested;      // uint per bucket
  gpu::Buffer bucketSlot;     // int per bucket, −1 when not resident
  gpu::Buffer slotBucket;     // int per slot, −1 when empty
  gpu::Buffer freshSlots;     // [0] count, then the slots inserted this frame (to synthesize)
  gpu::Buffer fillArgs;       // VkDispatchIndirectCommand of the fill pass
  gpu::Buffer data;           // capacity × segments × joints JointMatrix (the SSBO ring)
  gpu::Buffer segmentFrames;  // ivec2 per segment
};

// A disabled cache still gets small buffers so the pose pass always has its bindings.
GpuMotionCache makeGpuMotionCache(const gpu::Context& context, const anim::MotionPair& pair,
                                  const MotionCacheOptions& options);
MotionCacheStats readCacheStats(const GpuMotionCache& cache);

}  // namespace throng::synth
