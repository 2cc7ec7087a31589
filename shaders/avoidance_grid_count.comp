#version 450
#extension GL_GOOGLE_include_directive : require
// Counting sort, pass 1: each agent's cell, and its rank among the agents of that cell (the
// atomic's return value, so pass 3 needs no second atomic and no per-cell sort).
// CPU twin: crowd::buildGridCpu.
#include "crowd_types.h"
#include "avoidance_common.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = 1) writeonly buffer CellRank { uvec2 cellRank[]; };
layout(std430, binding = 2) buffer Counts { uint counts[]; };
layout(push_constant) uniform Push { GridPush push; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.agentCount) return;
  uint cell = cellIndex(cellCoord(placement[i].xz, push.invCellSize), push.widthShift, push.rowMask);
  cellRank[i] = uvec2(cell, atomicAdd(counts[cell], 1u));
}
