#pragma once
// Helpers shared by the clip preparation steps (clip_prep*.cpp): rotation distances, yaw
// removal, forward kinematics of one frame and the check for a capture's T-pose frame.
#include <vector>

#include <glm/glm.hpp>

#include "anim/clip.h"

namespace throng::anim::prep {

inline glm::vec4 conjugate(glm::vec4 q) {
  return glm::vec4(-q.x, -q.y, -q.z, q.w);
}

// Angle in [0, π] of the rotation taking `a` to `b` (atan2 form: exact near 0, where acos
// of the dot product loses half the digits).
float rotationAngle(glm::vec4 a, glm::vec4 b);

// Rotation vector (axis × angle, radians) of a unit quaternion, shortest arc.
glm::vec3 rotationVector(glm::vec4 q);

// `q` without its twist about world +y (heading): the tilt that is left, so two frames
// facing different directions compare by pitch and roll only.
glm::vec4 removeYaw(glm::vec4 q);

// Global position of every joint at `frame` (root at rootPositions[frame], the others at
// their offsets of that frame: Clip::offset).
std::vector<glm::vec3> globalPositions(const Clip& clip, int frame);

// Mean over joints of the rotation angle between frames a and b.
float meanPoseAngle(const Clip& clip, int a, int b);

// 1 when frame 0 is a calibration T-pose that the motion does not continue from (CMU
// captures start with one), else 0.
int firstUsableFrame(const Clip& clip);

// Throws an Error naming the clip unless its arrays match frameCount and jointCount
// (animatedOffsets: empty or one per joint per frame).
void checkClip(const Clip& clip);

}  // namespace throng::anim::prep
