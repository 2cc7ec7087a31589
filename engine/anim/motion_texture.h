#pragma once
// Motion textures (docs/design.md): width 2·J, height F, RGBA32F. Texel (2j, f) is joint j's local
// rotation at frame f (x,y,z,w); texel (2j+1, f) its offset from the parent (root: global
// position at frame f).
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "anim/clip.h"

namespace throng::anim {

struct MotionTexture {
  int jointCount = 0;
  int frameCount = 0;
  float frameTime = 0.0f;
  glm::vec3 cycleTravel{0.0f};    // root displacement over one cycle
  std::vector<glm::vec4> texels;  // frameCount rows of 2·jointCount texels

  int width() const { return 2 * jointCount; }
  float duration() const { return frameCount * frameTime; }
  const glm::vec4& texel(int x, int frame) const { return texels[size_t(frame) * width() + x]; }
  glm::vec4 rotation(int frame, int joint) const { return texel(2 * joint, frame); }
  glm::vec3 offset(int frame, int joint) const { return glm::vec3(texel(2 * joint + 1, frame)); }
};

MotionTexture bakeMotionTexture(const Clip& clip);

// What the synthesizer needs of a slow/fast pair: both textures, the shared parent array and
// the radius of each joint's drawn ellipsoid.
struct MotionPair {
  MotionTexture slow;
  MotionTexture fast;
  std::vector<int32_t> parents;
  std::vector<float> jointRadius;
  // Per joint: true when its offset changes from frame to frame in either clip (the root's
  // position always does). Other joints' offsets are constants the pose pass reads once.
  std::vector<bool> animatedOffset;
  int jointCount() const { return slow.jointCount; }
};

// Throws Error when the clips do not share a skeleton topology.
MotionPair makeMotionPair(const Clip& slow, const Clip& fast);

// A clip's root speed: its cycle's ground travel over the cycle's duration (m/s; 0 for a clip
// that does not travel). Speed → w maps between the two clips' root speeds.
float clipRootSpeed(const MotionTexture& clip);

}  // namespace throng::anim
