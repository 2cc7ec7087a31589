#pragma once
// BVH Euler angles to unit quaternions (x,y,z,w), honouring each joint's channel order.
#include <span>

#include <glm/glm.hpp>

#include "anim/skeleton.h"

namespace throng::anim {

// Rotation by `degrees` about the axis of a rotation channel (a position channel gives the
// identity).
glm::vec4 axisRotation(Channel channel, float degrees);

// A joint's local rotation from its channel values in file order. BVH semantics: for
// channels `Zrotation Xrotation Yrotation` the rotation is R = Rz * Rx * Ry, i.e. the
// first-listed axis is the outermost (applied last to a vector). Position channels are
// skipped. `values` must hold one value per channel.
glm::vec4 channelsToQuat(std::span<const Channel> channels, std::span<const float> values);

}  // namespace throng::anim
