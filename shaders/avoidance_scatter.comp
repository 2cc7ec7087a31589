#version 450
#extension GL_GOOGLE_include_directive : require
// Counting sort, pass 3: each agent takes a slot of its cell's range (in atomic order; the
// cell-sort pass makes the order within a cell deterministic).
#include "crowd_types.h"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer CellOf { uint cellOf[]; };
layout(std430, binding = 1) readonly buffer Starts { uint starts[]; };
layout(std430, binding = 2) buffer Cursor { uint cursor[]; };
layout(std430, binding = 3) writeonly buffer SortedIndex { uint sortedIndex[]; };
layout(push_constant) uniform Push { GridPush push; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.agentCount) return;
  uint h = cellOf[i];
  sortedIndex[starts[h] + atomicAdd(cursor[h], 1u)] = i;
}
