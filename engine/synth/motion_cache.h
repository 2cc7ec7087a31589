#pragma once
// The motion cache of the paper's §3.4, docs/design.md, resident on the GPU: key = speed weight
// quantized to a bucket, data = the synthesized character-space clip at that speed (cacheRowCount
// poses evenly spaced in phase, all joints). Lookup before synthesis, a miss synthesizes and
// inserts, FIFO eviction of the oldest entry when the byte budget is full — except an entry in
// use this frame: with more buckets requested than fit, the extra buckets stay uncached (their
// characters are synthesized in full) rather than thrash the cache, refilling entries every
// frame. A character whose bucket is resident does no blending and no hierarchy:
// A = M · cached pose. Each clip set of a crowd has its own cache and budget.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/motion_texture.h"
#include "anim/speed_buckets.h"
#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "gpu/program.h"
#include "synth/motion_gpu.h"

namespace throng::synth {

struct MotionCacheOptions {
  bool enabled = false;
  float bucketWidth = 0.05f;           // in speed-weight units (w ∈ [0, 1])
  uint64_t budgetBytes = 20ull << 20;  // paper: 20 MB
};

struct MotionCacheStats {
  uint32_t hits = 0, misses = 0, evictions = 0, entries = 0;
  uint64_t bytesUsed = 0, budgetBytes = 0;
};

// The cache keys characters by speed bucket (anim/speed_buckets.h).
using anim::bucketSpeed;
using anim::quantizeSpeed;
using anim::speedBucket;
using anim::speedBucketCount;

// Rows per cache entry: row r is the pose at phase r / R, sampled like the pose pass samples
// (continuously between motion-texture rows), and a cached character shows the row nearest its
// phase. Why dense rows and not interpolation between rows at playback: the renderer composes a
// cached character's joints straight from one entry (M · p, shaders/joint_fetch.glsl), and
// interpolating two poses' points is no rigid motion (lerped positions shorten the bones), while
// slerping would need the quaternions and the hierarchy again, the work the cache exists to
// skip. So R = ⌈kCacheRowsPerSecond × the longer cycle⌉ (at least the clips' own row counts):
// the row shown is within 1/960 s of the character's phase at any speed, so the pose advanced
// per frame varies by at most ±1/16 of a 30 fps frame's advance (±1/8 at 60 fps), well inside
// the gait's own variation (test_motion_continuity.cpp measures cached against uncached). The
// price is memory: a 0.77 s cycle of 31 joints (CMU) is 0.55 MB per bucket, 21 buckets of width
// 0.05 11.5 MB of the 20 MB budget.
constexpr float kCacheRowsPerSecond = 480.0f;
uint32_t cacheRowCount(const anim::MotionPair& pair);
// The row nearest a phase in [0, 1) (R wraps to row 0), and a row's phase; mirror
// cache_classify.comp and cache_fill.comp.
uint32_t cacheRow(float phase, uint32_t rows);
float cacheRowPhase(uint32_t row, uint32_t rows);

// Throws Error on a bucket width outside (0, 1] or an entry larger than the budget allows at 0.
void validateCacheOptions(const MotionCacheOptions& options);

struct GpuMotionCache {
  MotionCacheOptions options;
  uint32_t bucketCount = 0, rowCount = 0, capacity = 0, jointCount = 0;
  uint64_t entryBytes = 0;
  gpu::Buffer counters;    // CacheCounters, host-visible (read back every frame)
  gpu::Buffer requested;   // uint per bucket
  gpu::Buffer bucketSlot;  // int per bucket, −1 when not resident
  gpu::Buffer slotBucket;  // int per slot, −1 when empty
  gpu::Buffer freshSlots;  // [0] count, then the slots inserted this frame (to synthesize)
  gpu::Buffer fillArgs;    // VkDispatchIndirectCommand of the fill pass
  // The entries (capacity × rows × joints JointPoint, the SSBO ring) live in a data buffer
  // that several caches may share (one per clip set of a crowd, so that one draw composes
  // every cached character): this cache's entry 0 starts at point `dataBase` there.
  uint32_t dataBase = 0;
  uint64_t dataBytes() const { return uint64_t(capacity) * entryBytes; }
};

// A disabled cache still gets small buffers so the pose pass always has its bindings.
GpuMotionCache makeGpuMotionCache(const gpu::Context& context, const anim::MotionPair& pair,
                                  const MotionCacheOptions& options);
// A data buffer for these caches, one after the other: sets each cache's dataBase. Throws
// Error when the entries would not be addressable by a 32-bit point index.
gpu::Buffer makeCacheData(const gpu::Context& context, std::span<GpuMotionCache* const> caches);
// The far bodies' table beside a data buffer (gpu_types::FarBodyPose, shaders/coverage_types.h):
// one per pose of jointCount points, at the pose's first point index / jointCount.
VkDeviceSize farBodyPosesBytes(const gpu::Buffer& cacheData, uint32_t jointCount);
gpu::Buffer makeFarBodyPoses(const gpu::Context& context, const gpu::Buffer& cacheData,
                             uint32_t jointCount);
MotionCacheStats readCacheStats(const GpuMotionCache& cache);
// The sum over several caches (the clip sets of one crowd).
MotionCacheStats addCacheStats(const MotionCacheStats& a, const MotionCacheStats& b);

}  // namespace throng::synth
