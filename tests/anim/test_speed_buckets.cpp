// Speed buckets: the one rounding of speed weights (cache, retargeting, cloth tables).
#include <doctest/doctest.h>

#include <cmath>
#include <initializer_list>

#include "anim/speed_buckets.h"

using namespace throng::anim;

TEST_CASE("speed weights round to the nearest bucket and never past w = 1") {
  CHECK(speedBucketCount(0.05f) == 21u);
  CHECK(speedBucketCount(0.3f) == 4u);  // 0, 0.3, 0.6, 0.9
  CHECK(quantizeSpeed(0.0f, 0.05f) == 0.0f);
  CHECK(quantizeSpeed(0.26f, 0.05f) == doctest::Approx(0.25f));
  CHECK(quantizeSpeed(0.24f, 0.05f) == doctest::Approx(0.25f));
  CHECK(quantizeSpeed(0.2f, 0.3f) == doctest::Approx(0.3f));
  CHECK(quantizeSpeed(1.0f, 0.3f) == doctest::Approx(0.9f));  // the last bucket, not 1.2
  CHECK(quantizeSpeed(1.0f, 0.4f) == 1.0f);                   // bucket 3 at 1.2, capped to 1
  for (float width : {0.05f, 0.1f, 0.3f, 0.4f, 1.0f / 4095.0f}) {
    const uint32_t count = speedBucketCount(width);
    for (int i = 0; i <= 100; ++i) {
      const float w = float(i) / 100.0f;
      const uint32_t bucket = speedBucket(w, width, count);
      CHECK(bucket < count);
      CHECK(quantizeSpeed(w, width) == bucketSpeed(bucket, width));
      CHECK(quantizeSpeed(w, width) <= 1.0f);
      CHECK(std::abs(quantizeSpeed(w, width) - w) <= width * 0.5f + 1e-6f);
    }
  }
}
