// The best cycle in a raw capture: the pair of frames (start, end) whose poses and
// velocities match best, so that playing [start, end) on repeat has no visible seam.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "anim/clip_prep.h"
#include "anim/clip_prep_util.h"
#include "core/error.h"
#include "core/math.h"

namespace throng::anim {
namespace {

// Velocities are compared over this time so that a mismatch of 1 rad/s weighs like a pose
// mismatch of 0.1 rad; root heights are compared in metres (1 cm ≈ 0.6°).
constexpr float kVelocityTime = 0.1f;

// What a frame looks like to the loop search, from the first usable frame on.
struct LoopFeatures {
  int first = 0;
  int frames = 0;  // all frames of the clip; features exist for [first, frames)
  int joints = 0;
  std::vector<glm::vec4> pose;   // local rotations, the root's heading removed
  std::vector<glm::vec3> omega;  // local angular velocity per joint, rad/s
  std::vector<float> speed;      // horizontal root speed
  std::vector<float> height;     // root height
  std::vector<float> climb;      // vertical root velocity
  // Non-root joints' animated offsets and their velocities (empty when not animated):
  // compared in metres like the root, since a root that only slides leaves the hips'
  // height and bob to them.
  std::vector<glm::vec3> offset;
  std::vector<glm::vec3> offsetVelocity;

  size_t at(int frame, int joint = 0) const {
    return size_t(frame) * size_t(joints) + size_t(joint);
  }
};

LoopFeatures computeFeatures(const Clip& clip) {
  LoopFeatures out;
  out.first = prep::firstUsableFrame(clip);
  out.frames = clip.frameCount;
  out.joints = clip.jointCount();
  const size_t cells = size_t(out.frames) * size_t(out.joints);
  out.pose.resize(cells);
  out.omega.resize(cells);
  out.speed.resize(size_t(out.frames));
  out.height.resize(size_t(out.frames));
  out.climb.resize(size_t(out.frames));
  const bool animated = !clip.animatedOffsets.empty();
  if (animated) {
    out.offset = clip.animatedOffsets;
    out.offsetVelocity.assign(cells, glm::vec3(0.0f));
  }
  const int usable = out.frames - out.first;
  for (int f = out.first; f < out.frames; ++f) {
    // Central differences; at the ends the second-order one-sided ones, which agree with
    // central differences to O(dt²), so that a cut at the clip's first or last frame is
    // not penalised for the difference scheme. With 2 frames, a plain difference.
    int near = f + 1 < out.frames ? f + 1 : f - 1;
    int far = f + 2 < out.frames ? f + 2 : f - 2;
    bool central = f > out.first && f + 1 < out.frames;
    float scale = (f + 1 < out.frames ? 1.0f : -1.0f) / clip.frameTime;
    for (int j = 0; j < out.joints; ++j) {
      glm::vec4 q = clip.rotation(f, j);
      out.pose[out.at(f, j)] = j == 0 ? prep::removeYaw(q) : q;
      glm::vec3 omega(0.0f);
      if (central) {
        glm::vec4 delta =
            quatMul(prep::conjugate(clip.rotation(f - 1, j)), clip.rotation(f + 1, j));
        omega = prep::rotationVector(delta) * (0.5f / clip.frameTime);
      } else if (usable >= 3) {
        glm::vec3 r1 = prep::rotationVector(quatMul(prep::conjugate(q), clip.rotation(near, j)));
        glm::vec3 r2 = prep::rotationVector(quatMul(prep::conjugate(q), clip.rotation(far, j)));
        omega = (2.0f * r1 - 0.5f * r2) * scale;
      } else if (usable == 2) {
        omega = prep::rotationVector(quatMul(prep::conjugate(q), clip.rotation(near, j))) * scale;
      }
      out.omega[out.at(f, j)] = omega;
    }
    // The same differences for a series of positions, `stride` apart.
    auto derivative = [&](const std::vector<glm::vec3>& p, size_t stride, size_t index) {
      auto at = [&](int frame) { return p[size_t(frame) * stride + index]; };
      if (central) return (at(f + 1) - at(f - 1)) * (0.5f / clip.frameTime);
      if (usable >= 3) return (2.0f * (at(near) - at(f)) - 0.5f * (at(far) - at(f))) * scale;
      if (usable == 2) return (at(near) - at(f)) * scale;
      return glm::vec3(0.0f);
    };
    const std::vector<glm::vec3>& p = clip.rootPositions;
    glm::vec3 velocity = derivative(p, 1, 0);
    for (int j = 1; animated && j < out.joints; ++j) {
      out.offsetVelocity[out.at(f, j)] =
          derivative(clip.animatedOffsets, size_t(out.joints), size_t(j));
    }
    out.speed[size_t(f)] = glm::length(glm::vec2(velocity.x, velocity.z));
    out.height[size_t(f)] = p[size_t(f)].y;
    out.climb[size_t(f)] = velocity.y;
  }
  return out;
}

float distance(const LoopFeatures& features, int a, int b) {
  float pose = 0.0f;
  float omega = 0.0f;
  for (int j = 0; j < features.joints; ++j) {
    pose += prep::rotationAngle(features.pose[features.at(a, j)], features.pose[features.at(b, j)]);
    omega += glm::length(features.omega[features.at(a, j)] - features.omega[features.at(b, j)]);
  }
  const float joints = float(features.joints);
  const size_t fa = size_t(a), fb = size_t(b);
  float offsets = 0.0f;
  for (int j = 1; !features.offset.empty() && j < features.joints; ++j) {
    const size_t ja = features.at(a, j), jb = features.at(b, j);
    offsets +=
        glm::length(features.offset[ja] - features.offset[jb]) +
        kVelocityTime * glm::length(features.offsetVelocity[ja] - features.offsetVelocity[jb]);
  }
  return pose / joints + kVelocityTime * omega / joints + offsets +
         kVelocityTime * std::abs(features.speed[fa] - features.speed[fb]) +
         kVelocityTime * std::abs(features.climb[fa] - features.climb[fb]) +
         std::abs(features.height[fa] - features.height[fb]);
}

// Best (start, end) with end - start in [minLength, maxLength]; ties keep the earliest.
LoopCut search(const LoopFeatures& features, int minLength, int maxLength) {
  LoopCut best;
  best.error = std::numeric_limits<float>::infinity();
  const int last = features.frames - 1;
  for (int start = features.first; start + minLength <= last; ++start) {
    for (int end = start + minLength; end <= std::min(last, start + maxLength); ++end) {
      float error = distance(features, start, end);
      if (error < best.error) best = LoopCut{start, end, error};
    }
  }
  return best;
}

}  // namespace

float loopError(const Clip& clip, int start, int end) {
  prep::checkClip(clip);
  LoopFeatures features = computeFeatures(clip);
  if (start < features.first || end < features.first || start >= clip.frameCount ||
      end >= clip.frameCount) {
    fail("clip ", clip.name, ": frames ", start, " and ", end, " are outside the usable frames [",
         features.first, ", ", clip.frameCount, ")");
  }
  return distance(features, start, end);
}

LoopCut findBestLoop(const Clip& clip, int minFrames, int maxFrames) {
  prep::checkClip(clip);
  if (minFrames < 1 || maxFrames < minFrames) {
    fail("clip ", clip.name, ": the loop length range [", minFrames, ", ", maxFrames,
         "] frames is empty");
  }
  LoopFeatures features = computeFeatures(clip);
  const int usable = clip.frameCount - 1 - features.first;  // the end frame is compared, not kept
  if (usable < minFrames) {
    fail("clip ", clip.name, ": ", clip.frameCount - features.first,
         " usable frames cannot hold a loop of ", minFrames, " frames plus its closing frame");
  }
  maxFrames = std::min(maxFrames, usable);
  LoopCut best = search(features, minFrames, maxFrames);

  // Two or three gait cycles can match as well as one; keep the shortest that is nearly as
  // good so a clip is one cycle (half a cycle swaps the legs, so it never qualifies).
  for (int cycles = 3; cycles >= 2; --cycles) {
    int length = int(std::lround(float(best.length()) / float(cycles)));
    int lo = std::max(minFrames, length - 1);
    int hi = std::min(maxFrames, length + 1);
    if (lo > hi) continue;
    LoopCut shorter = search(features, lo, hi);
    if (shorter.error <= 1.2f * best.error + 0.01f) {
      best = shorter;
      break;
    }
  }
  return best;
}

}  // namespace throng::anim
