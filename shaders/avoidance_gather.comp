#version 450
#extension GL_GOOGLE_include_directive : require
// Counting sort, pass 5, one thread per slot: the agent's position and velocity in grid
// order for the neighbour scan, sorted[k] = (x, z, vx, vz) of agent sortedIndex[k].
#include "crowd_types.h"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = 1) readonly buffer Steer { vec4 steer[]; };
layout(std430, binding = 2) readonly buffer SortedIndex { uint sortedIndex[]; };
layout(std430, binding = 3) writeonly buffer Sorted { vec4 sorted[]; };
layout(push_constant) uniform Push { GridPush push; };

void main() {
  uint k = gl_GlobalInvocationID.x;
  if (k >= push.agentCount) return;
  uint i = sortedIndex[k];
  sorted[k] = vec4(placement[i].xz, steer[i].xy);
}
