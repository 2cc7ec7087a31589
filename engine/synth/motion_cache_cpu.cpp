#include "synth/motion_cache_cpu.h"

#include <cmath>

#include "anim/reference_synth.h"
#include "core/error.h"
#include "synth/cpu_synth.h"
#include "synth/joint_points.h"

namespace throng::synth {

MotionCacheCpu::MotionCacheCpu(const anim::MotionPair& pair, const MotionCacheOptions& options)
    : pair_(&pair), options_(options) {
  validateCacheOptions(options);
  bucketCount_ = speedBucketCount(options.bucketWidth);
  rows_ = cacheRowCount(pair);
  entryBytes_ = uint64_t(rows_) * pair.jointCount() * sizeof(JointPoint);
  capacity_ = options.enabled ? static_cast<uint32_t>(options.budgetBytes / entryBytes_) : 0u;
  bucketSlot_.assign(bucketCount_, -1);
  slotBucket_.assign(capacity_, -1);
  entries_.resize(capacity_);
  stats_.budgetBytes = options.budgetBytes;
}

void MotionCacheCpu::update(const crowd::Crowd& crowd) {
  // 0: not requested, 1: requested, 2: in use this frame (never evicted for another bucket of
  // the same frame). Mirrors cache_insert.comp.
  std::vector<uint8_t> requested(bucketCount_, 0);
  for (const glm::vec4& m : crowd.motion)
    requested[speedBucket(gpu_types::speedWeight(m), options_.bucketWidth, bucketCount_)] = 1;
  for (uint32_t b = 0; b < bucketCount_; ++b)
    if (requested[b] && bucketSlot_[b] >= 0) {
      ++stats_.hits;
      requested[b] = 2;
    }
  std::vector<uint32_t> fresh;
  for (uint32_t b = 0; b < bucketCount_; ++b) {
    if (requested[b] != 1) continue;
    ++stats_.misses;
    if (capacity_ == 0) continue;
    uint32_t slot = head_;
    int32_t previous = slotBucket_[slot];
    if (previous >= 0 && requested[size_t(previous)] != 0) continue;  // in use this frame
    if (previous >= 0) {
      bucketSlot_[previous] = -1;
      ++stats_.evictions;
    } else {
      ++stats_.entries;
    }
    bucketSlot_[b] = static_cast<int32_t>(slot);
    slotBucket_[slot] = static_cast<int32_t>(b);
    requested[b] = 2;
    fresh.push_back(slot);
    head_ = (slot + 1) % capacity_;
  }
  const size_t joints = static_cast<size_t>(pair_->jointCount());
  for (uint32_t slot : fresh) {
    if (slotBucket_[slot] < 0) continue;
    float w = bucketSpeed(static_cast<uint32_t>(slotBucket_[slot]), options_.bucketWidth);
    std::vector<JointPoint>& entry = entries_[slot];
    entry.assign(size_t(rows_) * joints, JointPoint{});
    for (uint32_t r = 0; r < rows_; ++r) {
      auto* points = reinterpret_cast<glm::vec4*>(&entry[r * joints]);
      anim::poseCharacterAt(*pair_, cacheRowPhase(r, rows_), w, 0.0f, glm::vec3(0.0f), 1.0f,
                            std::span<glm::vec4>(points, joints));
    }
  }
  stats_.bytesUsed = uint64_t(stats_.entries) * entryBytes_;
}

bool MotionCacheCpu::pose(const glm::vec4& placement, const glm::vec4& motion,
                          std::span<JointPoint> out) const {
  if (capacity_ == 0) return false;
  int32_t slot =
      bucketSlot_[speedBucket(gpu_types::speedWeight(motion), options_.bucketWidth, bucketCount_)];
  if (slot < 0) return false;
  const size_t joints = static_cast<size_t>(pair_->jointCount());
  const JointPoint* cached =
      &entries_[slot][size_t(cacheRow(gpu_types::cyclePhase(motion), rows_)) * joints];
  const float scale = gpu_types::characterScale(motion);
  for (size_t j = 0; j < joints; ++j)
    out[j].positionRadius = placeCachedPoint(cached[j].positionRadius, placement, scale);
  return true;
}

MotionCacheStats MotionCacheCpu::stats() const {
  return stats_;
}

void poseCrowdCpuCached(const anim::MotionPair& pair, const MotionCacheCpu& cache,
                        const crowd::Crowd& crowd, std::span<JointPoint> out, unsigned threads) {
  const size_t joints = static_cast<size_t>(pair.jointCount());
  THRONG_CHECK(out.size() >= crowd.size() * joints, "joint point output too small");
  parallelFor(crowd.size(), threads, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      std::span<JointPoint> mine = out.subspan(i * joints, joints);
      if (cache.pose(crowd.placement[i], crowd.motion[i], mine)) continue;
      anim::poseCharacter(pair, crowd.placement[i], crowd.motion[i],
                          std::span<glm::vec4>(reinterpret_cast<glm::vec4*>(mine.data()), joints));
    }
  });
}

}  // namespace throng::synth
