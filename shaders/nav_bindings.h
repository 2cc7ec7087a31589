// Descriptor binding numbers of the path-following pass (nav_follow.comp), named once here for
// the shader and engine/crowd/nav_jobs.cpp, like crowd_bindings.h.
#ifndef THRONG_NAV_BINDINGS_H
#define THRONG_NAV_BINDINGS_H

#ifdef __cplusplus
#include <cstdint>
namespace throng::gpu_types {
using uint = uint32_t;
#endif

const uint kNavFollowBindingPlacement = 0u;  // crowd placement (x, y, z, heading), read
const uint kNavFollowBindingPath = 1u;       // per agent: first waypoint, count, max speed bits
const uint kNavFollowBindingWaypoints = 2u;  // (x, z) per waypoint
const uint kNavFollowBindingProgress = 3u;   // per agent: the waypoint headed for, read and written
const uint kNavFollowBindingGoals = 4u;      // SteerBuffers::goals, written

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
