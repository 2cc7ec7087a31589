#version 450
#extension GL_GOOGLE_include_directive : require
// Counting sort, pass 1: each agent's hashed cell, and how many agents each cell holds.
// CPU twin: crowd::buildGridCpu.
#include "crowd_types.h"
#include "avoidance_common.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = 1) writeonly buffer CellOf { uint cellOf[]; };
layout(std430, binding = 2) buffer Counts { uint counts[]; };
layout(push_constant) uniform Push { GridPush push; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.agentCount) return;
  uint h = cellHash(cellCoord(placement[i].xz, push.invCellSize), push.cellCount);
  cellOf[i] = h;
  atomicAdd(counts[h], 1u);
}
