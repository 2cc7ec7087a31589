#include "anim/motion_texture.h"

#include <algorithm>

#include "core/error.h"

namespace throng::anim {

MotionTexture bakeMotionTexture(const Clip& clip) {
  if (clip.frameCount <= 0 || clip.jointCount() <= 0)
    fail(clip.name, ": empty clip cannot be baked");
  MotionTexture tex;
  tex.jointCount = clip.jointCount();
  tex.frameCount = clip.frameCount;
  tex.frameTime = clip.frameTime;
  tex.cycleTravel = clip.cycleTravel;
  tex.texels.resize(size_t(tex.frameCount) * tex.width());
  for (int f = 0; f < tex.frameCount; ++f) {
    glm::vec4* row = &tex.texels[size_t(f) * tex.width()];
    for (int j = 0; j < tex.jointCount; ++j) {
      row[2 * j] = clip.rotation(f, j);
      row[2 * j + 1] = glm::vec4(clip.offset(f, j), 0.0f);  // per frame when animated
    }
  }
  return tex;
}

namespace {
// Drawn thickness: proportional to the bone for limbs, never thinner than a finger.
float boneRadius(const Joint& joint, int index) {
  if (index == 0) return 0.11f;
  float length = glm::length(joint.offset);
  return std::clamp(0.16f * length, 0.022f, 0.09f);
}
}  // namespace

MotionPair makeMotionPair(const Clip& slow, const Clip& fast) {
  if (!slow.skeleton.sameTopology(fast.skeleton)) {
    fail("slow clip ", slow.name, " has ", slow.jointCount(), " joints and fast clip ", fast.name,
         " has ", fast.jointCount(),
         " (or different parents): a pair must share one skeleton topology");
  }
  MotionPair pair;
  pair.slow = bakeMotionTexture(slow);
  pair.fast = bakeMotionTexture(fast);
  pair.parents = slow.skeleton.parents();
  for (int j = 0; j < slow.jointCount(); ++j)
    pair.jointRadius.push_back(boneRadius(slow.skeleton.joints[j], j));
  for (int j = 0; j < slow.jointCount(); ++j) {
    bool animated = j == 0;
    for (const MotionTexture* tex : {&pair.slow, &pair.fast})
      for (int f = 1; f < tex->frameCount && !animated; ++f)
        animated = tex->offset(f, j) != tex->offset(0, j);
    pair.animatedOffset.push_back(animated);
  }
  return pair;
}

float clipRootSpeed(const MotionTexture& clip) {
  float duration = clip.duration();
  return duration > 0.0f ? glm::length(glm::vec2(clip.cycleTravel.x, clip.cycleTravel.z)) / duration
                         : 0.0f;
}

}  // namespace throng::anim
