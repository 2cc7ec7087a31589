#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Counting sort, pass 3: each agent's slot is its cell's start plus its rank there; the slot
// gets the agent's index and a copy of its position and velocity, sorted[k] = (x, z, vx, vz),
// which the neighbour scan reads (so the steering pass's writes never race with its reads).
#include "crowd_types.h"

layout(local_size_x = 64) in;
// Read and written in 64-bit words: lavapipe moves a vector one component per lane at a time.
layout(std430, binding = 0) readonly buffer Placement { u64vec2 placement[]; };  // (x, y), (z, heading)
layout(std430, binding = 1) readonly buffer Steer { uint64_t steer[]; };         // (vx, vz) at 2i
layout(std430, binding = 2) readonly buffer CellRank { uint64_t cellRank[]; };
layout(std430, binding = 3) readonly buffer Starts { uint starts[]; };
layout(std430, binding = 4) writeonly buffer SortedIndex { uint sortedIndex[]; };
layout(std430, binding = 5) writeonly buffer Sorted { u64vec2 sorted[]; };
layout(push_constant) uniform Push { GridPush push; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.agentCount) return;
  uvec2 cr = unpackUint2x32(cellRank[i]);
  uint slot = starts[cr.x] + cr.y;
  sortedIndex[slot] = i;
  u64vec2 place = placement[i];
  uint64_t xz = (place.x & 0xFFFFFFFFul) | (place.y << 32);
  sorted[slot] = u64vec2(xz, steer[2u * i]);
}
