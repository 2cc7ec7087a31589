#include "anim/clip_prep_util.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/math.h"

namespace throng::anim::prep {

float rotationAngle(glm::vec4 a, glm::vec4 b) {
  glm::vec4 r = quatMul(conjugate(a), b);
  return 2.0f * std::atan2(glm::length(glm::vec3(r)), std::abs(r.w));
}

glm::vec3 rotationVector(glm::vec4 q) {
  if (q.w < 0.0f) q = -q;
  glm::vec3 v(q);
  float s = glm::length(v);
  if (s < 1e-12f) return glm::vec3(0.0f);
  return v * (2.0f * std::atan2(s, q.w) / s);
}

glm::vec4 removeYaw(glm::vec4 q) {
  // Swing-twist: the twist about +y is (0, q.y, 0, q.w) normalised; q = twist * swing.
  float n = std::sqrt(q.y * q.y + q.w * q.w);
  if (n < 1e-6f) return q;  // a half turn about a horizontal axis: no defined heading
  glm::vec4 twist(0.0f, q.y / n, 0.0f, q.w / n);
  return quatMul(conjugate(twist), q);
}

std::vector<glm::vec3> globalPositions(const Clip& clip, int frame) {
  const int joints = clip.jointCount();
  std::vector<glm::vec3> position(static_cast<size_t>(joints));
  std::vector<glm::vec4> orientation(static_cast<size_t>(joints));
  for (int j = 0; j < joints; ++j) {
    const Joint& joint = clip.skeleton.joints[size_t(j)];
    glm::vec4 local = clip.rotation(frame, j);
    if (joint.parent < 0) {
      position[size_t(j)] = clip.offset(frame, j);
      orientation[size_t(j)] = local;
    } else {
      glm::vec4 parent = orientation[size_t(joint.parent)];
      position[size_t(j)] =
          position[size_t(joint.parent)] + quatRotate(parent, clip.offset(frame, j));
      orientation[size_t(j)] = quatMul(parent, local);
    }
  }
  return position;
}

float meanPoseAngle(const Clip& clip, int a, int b) {
  float sum = 0.0f;
  for (int j = 0; j < clip.jointCount(); ++j)
    sum += rotationAngle(clip.rotation(a, j), clip.rotation(b, j));
  return sum / float(clip.jointCount());
}

int firstUsableFrame(const Clip& clip) {
  if (clip.frameCount < 4 || clip.jointCount() == 0) return 0;
  // A T-pose frame is mostly identity rotations and far from frame 1 compared with how far
  // the motion itself moves per frame (frames 1→2 and 2→3).
  int identities = 0;
  for (int j = 0; j < clip.jointCount(); ++j) {
    if (rotationAngle(clip.rotation(0, j), glm::vec4(0, 0, 0, 1)) < 1e-3f) ++identities;
  }
  float jump = meanPoseAngle(clip, 0, 1);
  float step = 0.5f * (meanPoseAngle(clip, 1, 2) + meanPoseAngle(clip, 2, 3));
  bool mostlyIdentity = identities * 2 >= clip.jointCount();
  if (mostlyIdentity && jump > 3.0f * step + 0.02f) return 1;
  return jump > 8.0f * step + 0.05f ? 1 : 0;
}

void checkClip(const Clip& clip) {
  if (clip.frameCount < 1 || clip.jointCount() < 1) {
    fail("clip ", clip.name, ": expected at least one frame and one joint, found ", clip.frameCount,
         " frames and ", clip.jointCount(), " joints");
  }
  const size_t frames = size_t(clip.frameCount);
  if (clip.rotations.size() != frames * size_t(clip.jointCount()) ||
      clip.rootPositions.size() != frames || !(clip.frameTime > 0.0f)) {
    fail("clip ", clip.name, ": expected ", clip.frameCount, " frames × ", clip.jointCount(),
         " joints of rotations and one root position per frame at a positive frame time, found ",
         clip.rotations.size(), " rotations, ", clip.rootPositions.size(),
         " root positions, frame time ", clip.frameTime);
  }
  if (!clip.animatedOffsets.empty() && clip.animatedOffsets.size() != clip.rotations.size()) {
    fail("clip ", clip.name, ": expected no animated offsets or one per joint per frame (",
         clip.rotations.size(), "), found ", clip.animatedOffsets.size());
  }
  for (int j = 0; j < clip.jointCount(); ++j) {
    int parent = clip.skeleton.joints[size_t(j)].parent;
    if ((j == 0) != (parent < 0) || parent >= j) {
      fail("clip ", clip.name, ": joint ", j, " has parent ", parent,
           ", expected one root first and parents before their children");
    }
  }
}

}  // namespace throng::anim::prep
