#pragma once
// A crowd's (phase, w, wTarget, scale) over frames for the playback tests, without the
// synthesizer: each step advances the phase by about one primary frame of the character's bucket
// (sometimes two or three, as a dropped frame does), and at a cycle end w takes wTarget and a new
// target bucket is drawn — the synthesizer's rule.
#include <vector>

#include <glm/glm.hpp>

#include "cloth_fixtures.h"
#include "core/rng.h"
#include "secondary/cloth_playback.h"
#include "synth/motion_cache.h"

namespace throng::test {

struct MotionSim {
  secondary::RunGraphParams run;
  std::vector<glm::vec4> motion;
  Rng rng{7};
  float skipChance = 0.1f;

  // Speeds sit a little off the bucket centres (the cache-off case), never near a boundary.
  float bucketSpeed(uint32_t b) {
    return std::clamp(float(b) * run.bucketWidth + rng.uniform(-0.2f, 0.2f) * run.bucketWidth, 0.0f,
                      1.0f);
  }
  void init(uint32_t characters, uint64_t seed) {
    rng = Rng(seed);
    const uint32_t buckets = uint32_t(run.framesPerBucket.size());
    for (uint32_t i = 0; i < characters; ++i) {
      float w = bucketSpeed(rng.next() % buckets);
      motion.push_back(
          {rng.uniform(), w, bucketSpeed(rng.next() % buckets), rng.uniform(0.8f, 1.2f)});
    }
  }
  void step() {
    const uint32_t buckets = uint32_t(run.framesPerBucket.size());
    for (glm::vec4& m : motion) {
      uint32_t b = synth::speedBucket(m.y, run.bucketWidth, buckets);
      float frames = float(run.framesPerBucket[b]);
      float advance = rng.uniform() < skipChance ? float(2 + rng.next() % 2) : 1.0f;
      m.x += advance / frames;
      if (m.x >= 1.0f) {
        m.x -= std::floor(m.x);
        m.y = m.z;
        m.z = bucketSpeed(rng.next() % buckets);
      }
    }
  }
};

}  // namespace throng::test
