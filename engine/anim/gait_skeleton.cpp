// The gait's 25-joint skeleton and a plain forward-kinematics helper (double precision,
// BVH semantics) used to solve the root and by the tests to measure foot skate.
#include <cmath>
#include <string>

#include "anim/bvh_channels.h"
#include "anim/gait.h"
#include "core/error.h"

namespace throng::anim {
namespace {

const std::vector<Channel> kRootChannelList = {Channel::Xposition, Channel::Yposition,
                                               Channel::Zposition, Channel::Zrotation,
                                               Channel::Xrotation, Channel::Yrotation};
const std::vector<Channel> kJointChannelList = {Channel::Zrotation, Channel::Xrotation,
                                                Channel::Yrotation};

int addJoint(Skeleton& skeleton, const std::string& name, int parent, glm::vec3 offset) {
  Joint joint;
  joint.name = name;
  joint.parent = parent;
  joint.offset = offset;
  joint.channels = parent < 0 ? kRootChannelList : kJointChannelList;
  skeleton.joints.push_back(joint);
  return skeleton.jointCount() - 1;
}

void addArm(Skeleton& s, const std::string& side, float x, int chest) {
  int clavicle = addJoint(s, side + "Shoulder", chest, {0.02f * x, 0.06f, 0.0f});
  int upper = addJoint(s, side + "Arm", clavicle, {0.16f * x, -0.01f, 0.0f});
  int fore = addJoint(s, side + "ForeArm", upper, {0.0f, -0.30f, 0.0f});
  int hand = addJoint(s, side + "Hand", fore, {0.0f, -0.25f, 0.0f});
  int finger = addJoint(s, side + "HandIndex", hand, {0.0f, -0.09f, 0.0f});
  s.joints[size_t(finger)].endSite = glm::vec3(0.0f, -0.08f, 0.0f);
}

void addLeg(Skeleton& s, const std::string& side, float x) {
  int hip = addJoint(s, side + "UpLeg", 0, {0.09f * x, -0.04f, 0.0f});
  int knee = addJoint(s, side + "Leg", hip, {0.0f, -0.42f, 0.0f});
  int ankle = addJoint(s, side + "Foot", knee, {0.0f, -0.41f, 0.0f});
  int ball = addJoint(s, side + "ToeBase", ankle, {0.0f, -0.05f, 0.13f});
  s.joints[size_t(ball)].endSite = glm::vec3(0.0f, -0.015f, 0.06f);
}

glm::dmat3 axisMatrix(int axis, double degrees) {
  const double a = degrees * (3.14159265358979323846 / 180.0);
  const double c = std::cos(a), s = std::sin(a);
  glm::dmat3 m(1.0);  // column-major: m[column][row]
  int i = (axis + 1) % 3, j = (axis + 2) % 3;
  m[i][i] = c;
  m[j][j] = c;
  m[i][j] = s;
  m[j][i] = -s;
  return m;
}

template <typename T>
std::vector<glm::dvec3> forwardKinematicsImpl(const Skeleton& skeleton, std::span<const T> values) {
  const int jointCount = skeleton.jointCount();
  std::vector<glm::dvec3> positions(static_cast<size_t>(jointCount));
  std::vector<glm::dmat3> orientations(static_cast<size_t>(jointCount));
  size_t c = 0;
  for (int j = 0; j < jointCount; ++j) {
    const Joint& joint = skeleton.joints[size_t(j)];
    THRONG_CHECK(joint.parent < j, "joints must be stored parents first");
    THRONG_CHECK(c + joint.channels.size() <= values.size(), "one value per channel");
    glm::dvec3 offset(joint.offset);
    glm::dmat3 local(1.0);
    for (Channel channel : joint.channels) {
      double v = double(values[c++]);
      if (isRotation(channel)) {
        local = local * axisMatrix(channelAxis(channel), v);  // first listed is outermost
      } else if (joint.parent < 0) {
        offset[channelAxis(channel)] += v;  // as toClip: only the root's positions count
      }
    }
    if (joint.parent < 0) {
      positions[size_t(j)] = offset;
      orientations[size_t(j)] = local;
    } else {
      const size_t parent = size_t(joint.parent);
      positions[size_t(j)] = positions[parent] + orientations[parent] * offset;
      orientations[size_t(j)] = orientations[parent] * local;
    }
  }
  return positions;
}

}  // namespace

Skeleton gaitSkeleton() {
  Skeleton s;
  int hips = addJoint(s, "Hips", -1, {0.0f, 0.0f, 0.0f});
  int spine = addJoint(s, "Spine", hips, {0.0f, 0.10f, 0.0f});
  int spine1 = addJoint(s, "Spine1", spine, {0.0f, 0.12f, 0.0f});
  int spine2 = addJoint(s, "Spine2", spine1, {0.0f, 0.12f, 0.0f});
  int chest = addJoint(s, "Spine3", spine2, {0.0f, 0.10f, 0.0f});
  int neck = addJoint(s, "Neck", chest, {0.0f, 0.11f, 0.0f});
  int head = addJoint(s, "Head", neck, {0.0f, 0.10f, 0.02f});
  s.joints[size_t(head)].endSite = glm::vec3(0.0f, 0.15f, 0.0f);
  addArm(s, "Left", 1.0f, chest);  // the character faces +z, so its left is +x
  addArm(s, "Right", -1.0f, chest);
  addLeg(s, "Left", 1.0f);
  addLeg(s, "Right", -1.0f);
  return s;
}

std::vector<glm::dvec3> forwardKinematics(const Skeleton& skeleton,
                                          std::span<const double> channelValues) {
  return forwardKinematicsImpl(skeleton, channelValues);
}

std::vector<glm::dvec3> forwardKinematics(const Skeleton& skeleton,
                                          std::span<const float> channelValues) {
  return forwardKinematicsImpl(skeleton, channelValues);
}

}  // namespace throng::anim
