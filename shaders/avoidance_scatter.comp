#version 450
#extension GL_GOOGLE_include_directive : require
// Counting sort, pass 3: each agent's slot is its cell's start plus its rank there; the slot
// gets the agent's index and a copy of its position and velocity, sorted[k] = (x, z, vx, vz),
// which the neighbour scan reads (so the steering pass's writes never race with its reads).
#include "crowd_types.h"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = 1) readonly buffer Steer { vec4 steer[]; };
layout(std430, binding = 2) readonly buffer CellRank { uvec2 cellRank[]; };
layout(std430, binding = 3) readonly buffer Starts { uint starts[]; };
layout(std430, binding = 4) writeonly buffer SortedIndex { uint sortedIndex[]; };
layout(std430, binding = 5) writeonly buffer Sorted { vec4 sorted[]; };
layout(push_constant) uniform Push { GridPush push; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.agentCount) return;
  uvec2 cr = cellRank[i];
  uint slot = starts[cr.x] + cr.y;
  sortedIndex[slot] = i;
  sorted[slot] = vec4(placement[i].xz, steer[i].xy);
}
