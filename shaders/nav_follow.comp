#version 450
#extension GL_GOOGLE_include_directive : require
// Path following, every frame: each agent passes the waypoints it is near to or has rounded
// (past the bisector of the turn at the waypoint), then writes its steering goal for the
// avoidance pass: the final waypoint itself (it arrives and stops there), an intermediate one
// moved out along the same direction to maxSpeed · secondsLeft (full speed through corners).
// CPU twin: crowd::navFollowCpu.
#include "nav_types.h"
#include "nav_bindings.h"

layout(local_size_x = 64) in;
layout(std430, binding = kNavFollowBindingPlacement) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = kNavFollowBindingPath) readonly buffer NavPath { uvec4 navPath[]; };
layout(std430, binding = kNavFollowBindingWaypoints) readonly buffer Waypoints { vec2 waypoints[]; };
layout(std430, binding = kNavFollowBindingProgress) buffer Progress { uint progress[]; };
layout(std430, binding = kNavFollowBindingGoals) writeonly buffer Goals { vec4 goals[]; };
layout(push_constant) uniform Push { NavFollowPush push; };

vec2 unitOr0(vec2 v) {
  float len = length(v);
  return len > 1e-6 ? v / len : vec2(0.0);
}

// The agent at p has rounded waypoint c (reached from a, leaving for b).
bool rounded(vec2 p, vec2 a, vec2 c, vec2 b) {
  vec2 n = unitOr0(c - a) + unitOr0(b - c);
  return dot(n, n) > 1e-4 && dot(p - c, n) > 0.0;
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.agentCount) return;
  uvec4 path = navPath[i];
  if (path.y < 2u) {
    goals[i] = vec4(0.0);
    return;
  }
  vec2 p = placement[i].xz;
  uint last = path.y - 1u;
  uint k = clamp(progress[i], 1u, last);
  while (k < last) {
    vec2 c = waypoints[path.x + k];
    if (distance(p, c) >= push.reach &&
        !rounded(p, waypoints[path.x + k - 1u], c, waypoints[path.x + k + 1u]))
      break;
    k += 1u;
  }
  progress[i] = k;
  float maxSpeed = uintBitsToFloat(path.z);
  vec2 target = waypoints[path.x + k];
  if (k < last) {
    vec2 d = target - p;
    float len = length(d);
    float ahead = maxSpeed * push.secondsLeft;
    if (len > 1e-6 && len < ahead) target = p + d * (ahead / len);
  }
  goals[i] = vec4(target, maxSpeed, 1.0);
}
