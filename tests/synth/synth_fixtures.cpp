#include "synth_fixtures.h"

#include <algorithm>
#include <cmath>

#include "anim/default_clips.h"
#include "core/error.h"
#include "core/math.h"
#include "core/rng.h"

namespace throng::test {

const anim::MotionPair& builtInRunPair() {
  static const anim::MotionPair pair = [] {
    const anim::ClipPair clips = anim::defaultRunPair();
    return anim::makeMotionPair(clips.slow, clips.fast);
  }();
  return pair;
}

const anim::Skeleton& builtInRunSkeleton() {
  static const anim::ClipPair clips = anim::defaultRunPair();
  return clips.slow.skeleton;
}

anim::MotionPair syntheticPair(int joints, int slowFrames, int fastFrames, uint32_t seed) {
  Rng rng(seed);
  auto makeClip = [&](int frames, float speed, const std::vector<int>& parents,
                      const std::vector<glm::vec3>& offsets) {
    anim::Clip clip;
    clip.name = "synthetic";
    clip.frameCount = frames;
    clip.frameTime = 1.0f / 30.0f;
    for (int j = 0; j < joints; ++j) {
      anim::Joint joint;
      joint.name = concat("joint", j);  // (GCC 12 warns falsely on "j" + std::to_string(j))
      joint.parent = parents[j];
      joint.offset = offsets[j];
      clip.skeleton.joints.push_back(joint);
    }
    float travel = speed * frames * clip.frameTime;
    for (int f = 0; f < frames; ++f) {
      for (int j = 0; j < joints; ++j) {
        glm::vec4 q(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
        clip.rotations.push_back(glm::normalize(q + glm::vec4(0, 0, 0, 1.5f)));
      }
      float t = float(f) / frames;
      clip.rootPositions.push_back(glm::vec3(0.05f * std::sin(2 * kPi * t),
                                             0.95f + 0.04f * std::cos(4 * kPi * t), travel * t));
    }
    clip.cycleTravel = glm::vec3(0.0f, 0.0f, travel);
    return clip;
  };
  std::vector<int> parents(joints, -1);
  std::vector<glm::vec3> offsets(joints, glm::vec3(0.0f));
  for (int j = 1; j < joints; ++j) {
    parents[j] = static_cast<int>(rng.next() % j);
    offsets[j] =
        glm::vec3(rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f), rng.uniform(-0.3f, 0.3f));
  }
  anim::Clip slow = makeClip(slowFrames, 2.5f, parents, offsets);
  for (auto& o : offsets) o *= 1.05f;
  anim::Clip fast = makeClip(fastFrames, 4.5f, parents, offsets);
  return anim::makeMotionPair(slow, fast);
}

float maxAbsDifference(const float* a, const float* b, size_t count) {
  float worst = 0.0f;
  for (size_t i = 0; i < count; ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

}  // namespace throng::test
