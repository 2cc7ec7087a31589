#include "synth/motion_cache.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "anim/reference_synth.h"
#include "core/error.h"
#include "synth/coverage.h"
#include "synth/gpu_types.h"

namespace throng::synth {

uint32_t cacheRowCount(const anim::MotionPair& pair) {
  const float longest = std::max(pair.slow.duration(), pair.fast.duration());
  const auto dense = static_cast<uint32_t>(std::ceil(kCacheRowsPerSecond * longest));
  return std::max({dense, uint32_t(pair.slow.frameCount), uint32_t(pair.fast.frameCount), 1u});
}

uint32_t cacheRow(float phase, uint32_t rows) {
  auto row = static_cast<uint32_t>(phase * float(rows) + 0.5f);
  return row >= rows ? 0u : row;
}

float cacheRowPhase(uint32_t row, uint32_t rows) {
  return float(row) / float(rows);
}

void validateCacheOptions(const MotionCacheOptions& o) {
  if (!(o.bucketWidth > 0.0f && o.bucketWidth <= 1.0f))
    fail("--bucket-width: expected a speed-weight width in (0, 1], got ", o.bucketWidth);
}

namespace {
template <typename T>
gpu::Buffer filled(const gpu::Context& context, size_t count, T value, VkBufferUsageFlags extra = 0,
                   gpu::MemoryUse use = gpu::MemoryUse::DeviceLocal) {
  std::vector<T> values(std::max<size_t>(count, 1), value);
  return gpu::makeStorageBuffer<T>(context, values, use, extra);
}
}  // namespace

GpuMotionCache makeGpuMotionCache(const gpu::Context& context, const anim::MotionPair& pair,
                                  const MotionCacheOptions& options) {
  validateCacheOptions(options);
  GpuMotionCache cache;
  cache.options = options;
  cache.jointCount = static_cast<uint32_t>(pair.jointCount());
  cache.bucketCount = speedBucketCount(options.bucketWidth);
  cache.rowCount = cacheRowCount(pair);
  cache.entryBytes = uint64_t(cache.rowCount) * cache.jointCount * sizeof(JointPoint);
  cache.capacity =
      options.enabled ? static_cast<uint32_t>(options.budgetBytes / cache.entryBytes) : 0u;
  gpu_types::CacheCounters counters{};
  counters.capacity = cache.capacity;
  counters.bucketCount = cache.bucketCount;
  cache.counters =
      gpu::Buffer(context, sizeof(counters), gpu::kStorageUsage, gpu::MemoryUse::HostVisible);
  std::memcpy(cache.counters.mapped(), &counters, sizeof(counters));
  cache.requested = filled<uint32_t>(context, cache.bucketCount, 0u);
  cache.bucketSlot = filled<int32_t>(context, cache.bucketCount, -1);
  cache.slotBucket = filled<int32_t>(context, cache.capacity, -1);
  // Up to one entry per requested bucket is inserted in a frame, so bucketCount bounds the list.
  cache.freshSlots = filled<uint32_t>(context, size_t(cache.bucketCount) + 1, 0u);
  cache.fillArgs = filled<uint32_t>(context, 3, 0u, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
  return cache;
}

gpu::Buffer makeCacheData(const gpu::Context& context, std::span<GpuMotionCache* const> caches) {
  uint64_t points = 0;
  for (GpuMotionCache* cache : caches) {
    if (points > UINT32_MAX) break;
    cache->dataBase = static_cast<uint32_t>(points);
    points += cache->dataBytes() / sizeof(JointPoint);
  }
  if (points >= UINT32_MAX)
    fail("motion cache: ", points, " cached joint points are more than a 32-bit index reaches",
         " (lower the cache budget)");
  // A small buffer when every cache is disabled, so the passes always have their bindings.
  return gpu::Buffer(context,
                     std::max<uint64_t>(16 * sizeof(JointPoint), points * sizeof(JointPoint)),
                     gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
}

VkDeviceSize farBodyPosesBytes(const gpu::Buffer& cacheData, uint32_t jointCount) {
  const VkDeviceSize poses = cacheData.size() / sizeof(JointPoint) / std::max(jointCount, 1u);
  return (poses + 1) * sizeof(gpu_types::FarBodyPose);
}

gpu::Buffer makeFarBodyPoses(const gpu::Context& context, const gpu::Buffer& cacheData,
                             uint32_t jointCount) {
  return gpu::Buffer(context, farBodyPosesBytes(cacheData, jointCount), gpu::kStorageUsage,
                     gpu::MemoryUse::DeviceLocal);
}

MotionCacheStats addCacheStats(const MotionCacheStats& a, const MotionCacheStats& b) {
  return {a.hits + b.hits,       a.misses + b.misses,       a.evictions + b.evictions,
          a.entries + b.entries, a.bytesUsed + b.bytesUsed, a.budgetBytes + b.budgetBytes};
}

MotionCacheStats readCacheStats(const GpuMotionCache& cache) {
  gpu_types::CacheCounters c;
  std::memcpy(&c, cache.counters.mapped(), sizeof(c));
  MotionCacheStats stats{c.hits,
                         c.misses,
                         c.evictions,
                         c.entries,
                         uint64_t(c.entries) * cache.entryBytes,
                         cache.options.budgetBytes};
  return stats;
}

}  // namespace throng::synth
