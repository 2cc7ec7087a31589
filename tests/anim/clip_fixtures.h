#pragma once
// Synthetic clips with known answers for the clip preparation suites (test_clip_prep.cpp,
// test_clip_offsets.cpp), and forward kinematics of the feet for the ground checks.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include "anim/clip.h"
#include "anim/clip_prep_util.h"
#include "core/math.h"

namespace throng::test {

using anim::Clip;
using anim::Joint;
using anim::Skeleton;

// An upright 1.75 m skeleton in metres: hips at 0, head top at 0.8, soles at -0.95.
inline Skeleton personSkeleton() {
  Skeleton s;
  auto add = [&](const char* name, int parent, glm::vec3 offset) {
    s.joints.push_back(Joint{name, parent, offset, {}, std::nullopt});
  };
  add("Hips", -1, {0, 0, 0});
  add("Spine", 0, {0, 0.25f, 0});
  add("Head", 1, {0, 0.35f, 0});
  s.joints.back().endSite = glm::vec3(0, 0.2f, 0);
  for (int side = 0; side < 2; ++side) {
    float x = side == 0 ? 0.1f : -0.1f;
    int first = s.jointCount();
    add(side == 0 ? "LeftUpLeg" : "RightUpLeg", 0, {x, -0.05f, 0});
    add(side == 0 ? "LeftLeg" : "RightLeg", first, {0, -0.45f, 0});
    add(side == 0 ? "LeftFoot" : "RightFoot", first + 1, {0, -0.42f, 0});
    s.joints.back().endSite = glm::vec3(0, -0.03f, 0.12f);
  }
  return s;
}

inline glm::vec4 axisAngle(float angle, glm::vec3 axis) {
  return throng::toVec4(glm::angleAxis(angle, glm::normalize(axis)));
}

// A gait-like clip with an exact period of `period` frames: legs swing in antiphase (so half
// a period is a different pose), the body bobs twice per cycle and moves along `direction`.
// `wobble` (radians) adds a spine motion with twice the period: two cycles then match
// exactly, one only nearly, as in real capture.
inline Clip periodicClip(int frames, int period, glm::vec3 direction = {0, 0, 1},
                         float speed = 3.0f, float wobble = 0.0f) {
  Clip clip;
  clip.name = "periodic";
  clip.skeleton = personSkeleton();
  clip.frameCount = frames;
  clip.frameTime = 1.0f / 30.0f;
  float heading = std::atan2(direction.x, direction.z);
  for (int f = 0; f < frames; ++f) {
    float phase = 2.0f * throng::kPi * float(f) / float(period);
    float swing = 0.5f + 0.5f * std::sin(phase);  // left hip: lowest foot at 3/4 of the cycle
    float swingRight = 0.5f - 0.5f * std::sin(phase);
    glm::vec4 rotations[9] = {
        throng::quatMul(throng::yawQuat(heading),
                        axisAngle(0.1f + 0.05f * std::sin(2 * phase), {1, 0, 0.3f})),
        axisAngle(0.2f + 0.1f * std::sin(phase + 1.0f) + wobble * std::sin(0.5f * phase),
                  {0, 1, 0.2f}),
        axisAngle(0.15f * std::cos(phase), {1, 0.5f, 0}),
        axisAngle(swing, {1, 0, 0}),
        axisAngle(-0.4f - 0.3f * std::sin(phase + 0.5f), {1, 0, 0}),
        axisAngle(0.3f + 0.2f * std::cos(phase), {1, 0, 0.1f}),
        axisAngle(swingRight, {1, 0, 0}),
        axisAngle(-0.4f + 0.3f * std::sin(phase + 0.5f), {1, 0, 0}),
        axisAngle(0.3f - 0.2f * std::cos(phase), {1, 0, 0.1f}),
    };
    clip.rotations.insert(clip.rotations.end(), std::begin(rotations), std::end(rotations));
    glm::vec3 ahead = glm::normalize(direction) * (speed * clip.frameTime * float(f));
    clip.rootPositions.push_back(ahead + glm::vec3(0, 1.0f + 0.03f * std::cos(2 * phase), 0));
  }
  return clip;
}

// periodicClip with the root's height bob moved into its children's offsets, as Bandai Namco
// animates its hips under a root that only slides: every other joint stays where it was.
inline Clip withAnimatedOffsets(const Clip& clip) {
  Clip out = clip;
  const int joints = clip.jointCount();
  out.animatedOffsets.reserve(size_t(clip.frameCount) * size_t(joints));
  for (int f = 0; f < clip.frameCount; ++f) {
    glm::vec3 bob(0.0f, clip.rootPositions[size_t(f)].y - 1.0f, 0.0f);
    out.rootPositions[size_t(f)].y = 1.0f;
    glm::vec3 local = throng::quatRotate(anim::prep::conjugate(clip.rotation(f, 0)), bob);
    for (int j = 0; j < joints; ++j) {
      const Joint& joint = clip.skeleton.joints[size_t(j)];
      out.animatedOffsets.push_back(joint.offset + (joint.parent == 0 ? local : glm::vec3(0.0f)));
    }
  }
  return out;
}

// Lowest point of the feet (ankles, toes and their End Sites) at each frame, by forward
// kinematics over the clip's rotations and per-frame offsets.
inline std::vector<float> lowestFootPoints(const Clip& clip) {
  std::vector<float> lowest;
  for (int f = 0; f < clip.frameCount; ++f) {
    std::vector<glm::vec3> position = anim::prep::globalPositions(clip, f);
    std::vector<glm::vec4> orientation(size_t(clip.jointCount()));
    float low = 1e9f;
    for (int j = 0; j < clip.jointCount(); ++j) {
      const Joint& joint = clip.skeleton.joints[size_t(j)];
      glm::vec4 parent =
          joint.parent < 0 ? glm::vec4(0, 0, 0, 1) : orientation[size_t(joint.parent)];
      orientation[size_t(j)] = throng::quatMul(parent, clip.rotation(f, j));
      if (joint.name.find("Foot") == std::string::npos &&
          joint.name.find("Toe") == std::string::npos)
        continue;
      low = std::min(low, position[size_t(j)].y);
      if (joint.endSite) {
        glm::vec3 tip =
            position[size_t(j)] + throng::quatRotate(orientation[size_t(j)], *joint.endSite);
        low = std::min(low, tip.y);
      }
    }
    lowest.push_back(low);
  }
  return lowest;
}

}  // namespace throng::test
