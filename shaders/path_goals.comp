#version 450
#extension GL_GOOGLE_include_directive : require
// Path-vector waypoints for one simulated second, on the GPU (once per second, not per step):
// goal[i] = (start + R · Σ_{k≤j} P_k, max speed, 1) for agents active during that second, 0 for
// the others. A source's vectors loop: past its end the agent starts over from where it is,
// unless the source holds its end (kPathHoldsEnd), when its last waypoint stays the goal.
// CPU twin: crowd::writeGoals (AgentPaths::waypoint).
#include "crowd_types.h"
#include "crowd_bindings.h"

layout(local_size_x = 64) in;
layout(std430, binding = kGoalsBindingAgentStart) readonly buffer AgentStart { vec4 agentStart[]; };  // start x, z, rotation cos, sin
layout(std430, binding = kGoalsBindingAgentInfo) readonly buffer AgentInfo { uvec4 agentInfo[]; };  // source, first second, last second, max speed bits
layout(std430, binding = kGoalsBindingSourceRange) readonly buffer SourceRange { uvec2 sourceRange[]; };  // first cumulative entry, vector count n
layout(std430, binding = kGoalsBindingCumulative) readonly buffer Cumulative { vec2 cumulative[]; };  // per source: n + 1 partial sums
layout(std430, binding = kGoalsBindingGoals) writeonly buffer Goals { vec4 goals[]; };
layout(push_constant) uniform Push { GoalPush push; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.agentCount) return;
  uvec4 info = agentInfo[i];
  if (push.second < info.y || push.second >= info.z) {
    goals[i] = vec4(0.0);
    return;
  }
  uvec2 range = sourceRange[info.x];
  uint n = range.y & ~kPathHoldsEnd;
  uint j = push.second - info.y + 1u;
  if ((range.y & kPathHoldsEnd) != 0u) j = min(j, n);
  vec2 offset = j <= n ? cumulative[range.x + j] : float(j / n) * cumulative[range.x + n] + cumulative[range.x + j % n];
  vec4 start = agentStart[i];
  vec2 w = start.xy + vec2(start.z * offset.x - start.w * offset.y, start.w * offset.x + start.z * offset.y);
  goals[i] = vec4(w, uintBitsToFloat(info.w), 1.0);
}
