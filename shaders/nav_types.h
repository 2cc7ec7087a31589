// Structs of the path-following pass (nav_follow.comp), shared by C++ and GLSL like
// crowd_types.h. C++ includes this file through crowd/nav_jobs.h (static_asserts).
#ifndef THRONG_NAV_TYPES_H
#define THRONG_NAV_TYPES_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace throng::gpu_types {
using uint = uint32_t;
#endif

// Per-agent buffers of the pass:
//   navPath[i]   = (first waypoint, waypoint count, max speed (float bits), 0)  count 0: no path
//   waypoints[k] = (x, z)  every agent's path one after another (CSR); a path's first entry is
//                  where it was planned from (the direction into its first corner)
//   progress[i]  = the waypoint the agent heads for (1 ..< count), kept between frames

// Push constants of the path-following pass.
struct NavFollowPush {
  uint agentCount;
  float reach;        // a waypoint nearer than this (m) is passed
  float secondsLeft;  // the avoidance pass's time to the goal: intermediate targets are moved
                      // out to maxSpeed · secondsLeft so agents walk at full speed through corners
  uint pad0;
};

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
