// Speed buckets; mirrors engine/anim/speed_buckets.h (the one rounding of speed weights).
#ifndef THRONG_SPEED_BUCKETS_GLSL
#define THRONG_SPEED_BUCKETS_GLSL
uint speedBucket(float w, float width, uint bucketCount) {
  return min(uint(w / width + 0.5), bucketCount - 1u);
}
float bucketSpeed(uint bucket, float width) { return min(float(bucket) * width, 1.0); }
// w in [0, 1] rounded to its bucket's speed; the bucket never passes the last one there, so
// the count (a C++ lround) is not needed.
float quantizeSpeed(float w, float width) { return bucketSpeed(uint(w / width + 0.5), width); }
#endif
