// Speed buckets of the motion cache; mirrors engine/synth/motion_cache.h.
#ifndef THRONG_CACHE_COMMON_GLSL
#define THRONG_CACHE_COMMON_GLSL
uint speedBucket(float w, float width, uint bucketCount) {
  return min(uint(w / width + 0.5), bucketCount - 1u);
}
float bucketSpeed(uint bucket, float width) { return min(float(bucket) * width, 1.0); }
#endif
