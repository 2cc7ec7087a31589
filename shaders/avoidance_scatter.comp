#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Counting sort, pass 3: each agent's slot is its cell's start plus its rank there; the slot
// gets the agent's index and a copy of its position and velocity, sorted[k] = (x, z, vx, vz),
// which the neighbour scan reads (so the steering pass's writes never race with its reads).
#include "crowd_types.h"
#include "crowd_bindings.h"

layout(local_size_x = 64) in;
// Reads as texels (one gather for all lanes on lavapipe, where a storage load loops over them);
// writes in 64-bit words (lavapipe stores a vector one component per lane at a time).
layout(binding = kGridScatterBindingPlacement) uniform samplerBuffer placementTexels;  // (x, y, z, heading)
layout(binding = kGridScatterBindingSteer) uniform samplerBuffer steerTexels;  // (vx, vz, speed, flags)
layout(binding = kGridScatterBindingCellRank) uniform usamplerBuffer cellRankTexels;  // (cell, rank)
layout(binding = kGridScatterBindingStarts) uniform usamplerBuffer startTexels;
layout(std430, binding = kGridScatterBindingSortedIndex) writeonly buffer SortedIndex { uint sortedIndex[]; };
layout(std430, binding = kGridScatterBindingSorted) writeonly buffer Sorted { u64vec2 sorted[]; };
layout(push_constant) uniform Push { GridPush push; };

void main() {
  uint agentCount = push.agentCount;
  uint i = gl_GlobalInvocationID.x;
  if (i >= agentCount) return;
  uvec2 cr = texelFetch(cellRankTexels, int(i)).xy;
  uint slot = texelFetch(startTexels, int(cr.x)).x + cr.y;
  sortedIndex[slot] = i;
  vec2 xz = texelFetch(placementTexels, int(i)).xz;
  vec2 v = texelFetch(steerTexels, int(i)).xy;
  sorted[slot] = u64vec2(packUint2x32(floatBitsToUint(xz)), packUint2x32(floatBitsToUint(v)));
}
