#include "anim/animation_export.h"

#include <cmath>

#include <glm/gtx/euler_angles.hpp>

#include "core/error.h"
#include "shaders/shared_types.h"

namespace throng::anim {
namespace {

glm::quat toQuat(const glm::vec4& q) {
  return glm::quat(q.w, q.x, q.y, q.z);
}

glm::quat yaw(float heading) {
  return glm::angleAxis(heading, glm::vec3(0.0f, 1.0f, 0.0f));
}

}  // namespace

JointAnimation beginAnimation(const MotionPair& pair, const Skeleton& skeleton, float dt,
                              std::string name) {
  if (skeleton.jointCount() != pair.jointCount())
    fail("export: the skeleton has ", skeleton.jointCount(), " joints, the clip pair ",
         pair.jointCount());
  if (!(dt > 0.0f)) fail("export: expected a frame time > 0, got ", dt);
  JointAnimation out;
  out.name = std::move(name);
  out.skeleton = skeleton;
  out.frameTime = dt;
  // Rest offsets are set from the first frame; the root's is zero because BVH adds a root's
  // position channels to its OFFSET (other joints' position channels replace it).
  for (Joint& joint : out.skeleton.joints) joint.offset = glm::vec3(0.0f);
  return out;
}

// One frame: the pose in character space, made joint-local and placed in the world.
void appendPose(const MotionPair& pair, const glm::vec4& placement, const glm::vec4& motion,
                JointAnimation& out) {
  thread_local std::vector<PoseJoint> pose;
  pose.resize(size_t(pair.jointCount()));
  poseCharacterSpace(pair, gpu_types::cyclePhase(motion), gpu_types::speedWeight(motion), pose);
  const float scale = gpu_types::characterScale(motion);
  for (int j = 0; j < pair.jointCount(); ++j) {
    const int p = pair.parents[size_t(j)];
    const glm::quat rotation = toQuat(pose[size_t(j)].rotation);
    if (p < 0) {
      out.rotations.push_back(glm::normalize(yaw(placement.w) * rotation));
      out.translations.push_back(glm::vec3(placement) + scale * pose[size_t(j)].position);
    } else {
      const glm::quat parentInverse = glm::inverse(toQuat(pose[size_t(p)].rotation));
      out.rotations.push_back(glm::normalize(parentInverse * rotation));
      out.translations.push_back(
          scale * (parentInverse * (pose[size_t(j)].position - pose[size_t(p)].position)));
      if (out.frameCount == 0) out.skeleton.joints[size_t(j)].offset = out.translations.back();
    }
  }
  ++out.frameCount;
}

JointAnimation recordCharacter(const MotionPair& pair, const Skeleton& skeleton,
                               glm::vec4 placement, glm::vec4 motion,
                               const RecordOptions& options) {
  if (options.frames < 1) fail("export: expected frames >= 1, got ", options.frames);
  JointAnimation out = beginAnimation(pair, skeleton, options.dt, "");
  for (int f = 0; f < options.frames; ++f) {
    appendPose(pair, placement, motion, out);
    const SpeedRetarget retarget =
        size_t(f) < options.retargets.size() ? options.retargets[size_t(f)] : SpeedRetarget{};
    stepCharacter(pair, placement, motion, options.dt, options.steering, retarget,
                  options.character);
  }
  return out;
}

std::vector<glm::vec3> worldPositions(const JointAnimation& a, int frame) {
  std::vector<glm::vec3> position(size_t(a.jointCount()));
  std::vector<glm::quat> rotation(size_t(a.jointCount()));
  for (int j = 0; j < a.jointCount(); ++j) {
    const int p = a.skeleton.joints[size_t(j)].parent;
    if (p < 0) {
      position[size_t(j)] = a.translation(frame, j);
      rotation[size_t(j)] = a.rotation(frame, j);
    } else {
      position[size_t(j)] = position[size_t(p)] + rotation[size_t(p)] * a.translation(frame, j);
      rotation[size_t(j)] = rotation[size_t(p)] * a.rotation(frame, j);
    }
  }
  return position;
}

glm::vec3 eulerZxyDegrees(const glm::quat& q) {
  float z = 0, x = 0, y = 0;
  glm::extractEulerAngleZXY(glm::mat4_cast(glm::normalize(q)), z, x, y);
  return glm::degrees(glm::vec3(z, x, y));
}

RawClip toBvhClip(const JointAnimation& a) {
  RawClip clip;
  clip.sourceName = a.name;
  clip.skeleton = a.skeleton;
  clip.frameCount = a.frameCount;
  clip.frameTime = a.frameTime;
  const std::vector<Channel> channels = {Channel::Xposition, Channel::Yposition,
                                         Channel::Zposition, Channel::Zrotation,
                                         Channel::Xrotation, Channel::Yrotation};
  for (Joint& joint : clip.skeleton.joints) joint.channels = channels;
  clip.channelCount = 6 * a.jointCount();
  clip.values.reserve(size_t(a.frameCount) * size_t(clip.channelCount));
  for (int f = 0; f < a.frameCount; ++f) {
    for (int j = 0; j < a.jointCount(); ++j) {
      const glm::vec3 t = a.translation(f, j);
      const glm::vec3 e = eulerZxyDegrees(a.rotation(f, j));
      clip.values.insert(clip.values.end(), {t.x, t.y, t.z, e.x, e.y, e.z});
    }
  }
  return clip;
}

}  // namespace throng::anim
