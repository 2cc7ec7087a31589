#pragma once
// The poses' stored form (gpu_types::JointPoint: a joint's position and its bone's drawn radius)
// turned into the draw matrices their readers test and draw (gpu_types::boneMatrix), and the
// motion cache's placement of a character-space point. CPU twins of joint_fetch.glsl and
// cached_pose.glsl.
#include <cstdint>
#include <span>
#include <vector>

#include "synth/gpu_types.h"

namespace throng::synth {

// Joint j's draw matrix from one character's points (parents: the skeleton's, -1 for the root).
JointMatrix jointMatrixAt(std::span<const JointPoint> character, std::span<const int32_t> parents,
                          size_t j);
// Every joint's draw matrix of characters stored one after another, parents.size() joints each.
std::vector<JointMatrix> jointMatrices(std::span<const JointPoint> points,
                                       std::span<const int32_t> parents);
// M · p for M = T(place.xyz) · R_y(place.w) · S(scale); the radius scales too.
glm::vec4 placeCachedPoint(glm::vec4 p, glm::vec4 place, float scale);

}  // namespace throng::synth
