#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Counting sort, pass 1: each agent's cell, and its rank among the agents of that cell (the
// atomic's return value, so pass 3 needs no second atomic and no per-cell sort).
// CPU twin: crowd::buildGridCpu.
#include "crowd_types.h"
#include "crowd_bindings.h"
#include "avoidance_common.glsl"

layout(local_size_x = 64) in;
// Read as texels: lavapipe gathers a texel for all lanes, loops over the lanes for a storage load.
layout(binding = kGridCountBindingPlacement) uniform samplerBuffer placementTexels;
layout(std430, binding = kGridCountBindingCellRank) writeonly buffer CellRank { uint64_t cellRank[]; };
layout(std430, binding = kGridCountBindingCounts) buffer Counts { uint counts[]; };
layout(push_constant) uniform Push { GridPush push; };

void main() {
  GridPush p = push;  // before the branch: inside one, lavapipe gathers push constants lane by lane
  uint i = gl_GlobalInvocationID.x;
  if (i >= p.agentCount) return;
  vec2 xz = texelFetch(placementTexels, int(i)).xz;
  uint cell = cellIndex(cellCoord(xz, vec2(p.invCellX, p.invCellZ)), p.widthShift, p.rowMask);
  cellRank[i] = packUint2x32(uvec2(cell, atomicAdd(counts[cell], 1u)));
}
