#include "anim/speed_buckets.h"

#include "shaders/shared_types.h"

#include <algorithm>
#include <cmath>

namespace throng::anim {

uint32_t speedBucketCount(float bucketWidth) {
  return static_cast<uint32_t>(std::lround(1.0f / bucketWidth)) + 1u;
}

uint32_t speedBucket(float w, float bucketWidth, uint32_t bucketCount) {
  return std::min(static_cast<uint32_t>(w / bucketWidth + 0.5f), bucketCount - 1u);
}

float bucketSpeed(uint32_t bucket, float bucketWidth) {
  return std::min(float(bucket) * bucketWidth, 1.0f);
}

float quantizeSpeed(float w, float bucketWidth) {
  return bucketSpeed(speedBucket(w, bucketWidth, speedBucketCount(bucketWidth)), bucketWidth);
}

void quantizeSpeeds(std::span<glm::vec4> motion, float bucketWidth) {
  for (glm::vec4& m : motion) {
    const float w = quantizeSpeed(gpu_types::speedWeight(m), bucketWidth);
    m = gpu_types::withTargetSpeedWeight(gpu_types::withSpeedWeight(m, w), w);
  }
}

}  // namespace throng::anim
