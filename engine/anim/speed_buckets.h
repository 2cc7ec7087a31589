#pragma once
// Speed buckets: the speed weight w in [0, 1] rounded to multiples of a bucket width. The one
// rounding used by the motion cache, speed retargeting (CPU twin and shaders/speed_buckets.glsl)
// and the cloth database's per-bucket tables.
#include <cstdint>
#include <span>

#include <glm/glm.hpp>

namespace throng::anim {

// Buckets 0..count-1 cover w = 0, width, 2·width, ... up to 1.
uint32_t speedBucketCount(float bucketWidth);
// The bucket nearest w, at most bucketCount - 1.
uint32_t speedBucket(float w, float bucketWidth, uint32_t bucketCount);
// The speed weight of a bucket (at most 1).
float bucketSpeed(uint32_t bucket, float bucketWidth);
// w rounded to its bucket's speed (what a cached pose is synthesized at).
float quantizeSpeed(float w, float bucketWidth);
// Every character's speed weight and target on its bucket's speed (motion vectors as in
// shaders/shared_types.h), so that a crowd starts on cached speeds.
void quantizeSpeeds(std::span<glm::vec4> motion, float bucketWidth);

}  // namespace throng::anim
