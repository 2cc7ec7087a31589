#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Counting sort, pass 1: each agent's cell, and its rank among the agents of that cell (the
// atomic's return value, so pass 3 needs no second atomic and no per-cell sort).
// CPU twin: crowd::buildGridCpu.
#include "crowd_types.h"
#include "avoidance_common.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Placement { u64vec2 placement[]; };  // 64-bit words, as in the scatter
layout(std430, binding = 1) writeonly buffer CellRank { uint64_t cellRank[]; };
layout(std430, binding = 2) buffer Counts { uint counts[]; };
layout(push_constant) uniform Push { GridPush push; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.agentCount) return;
  u64vec2 place = placement[i];
  vec2 xz = vec2(uintBitsToFloat(uint(place.x)), uintBitsToFloat(uint(place.y)));
  uint cell = cellIndex(cellCoord(xz, push.invCellSize), push.widthShift, push.rowMask);
  cellRank[i] = packUint2x32(uvec2(cell, atomicAdd(counts[cell], 1u)));
}
