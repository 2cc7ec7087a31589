#pragma once
// placementJoints (anim/skeleton.h) for a motion pair, which keeps no skeleton: decided on the
// pair's first slow frame, the pose the renderer draws.
#include <vector>

#include "anim/motion_texture.h"

namespace throng::anim {

std::vector<bool> placementJoints(const MotionPair& pair);

}  // namespace throng::anim
