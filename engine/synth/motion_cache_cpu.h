#pragma once
// CPU twin of the GPU motion cache: the same buckets, the same FIFO decisions in the same order,
// the same cached character-space poses and their placement M · p.
#include <span>
#include <vector>

#include "anim/motion_texture.h"
#include "crowd/crowd.h"
#include "synth/gpu_types.h"
#include "synth/motion_cache.h"

namespace throng::synth {

class MotionCacheCpu {
 public:
  MotionCacheCpu(const anim::MotionPair& pair, const MotionCacheOptions& options);

  // Lookup + insert + fill for one frame of the crowd (after its root motion step).
  void update(const crowd::Crowd& crowd);
  // Joint points of one character from its cached pose; false when its bucket is not resident.
  bool pose(const glm::vec4& placement, const glm::vec4& motion, std::span<JointPoint> out) const;
  MotionCacheStats stats() const;
  uint32_t capacity() const { return capacity_; }
  uint32_t rows() const { return rows_; }

 private:
  const anim::MotionPair* pair_;
  MotionCacheOptions options_;
  uint32_t bucketCount_ = 0, capacity_ = 0, head_ = 0;
  uint64_t entryBytes_ = 0;
  uint32_t rows_ = 0;
  std::vector<int32_t> bucketSlot_, slotBucket_;
  std::vector<std::vector<JointPoint>> entries_;  // per slot: rows × joints
  MotionCacheStats stats_;
};

// The CPU path for a crowd with a cache: cached characters from the cache, others synthesized.
void poseCrowdCpuCached(const anim::MotionPair& pair, const MotionCacheCpu& cache,
                        const crowd::Crowd& crowd, std::span<JointPoint> out, unsigned threads = 1);

}  // namespace throng::synth
