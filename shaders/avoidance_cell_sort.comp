#version 450
#extension GL_GOOGLE_include_directive : require
// Counting sort, pass 4, one thread per cell: agents of the cell by increasing index (so GPU
// and CPU visit neighbours in one order and sum forces alike). Pass 5 (avoidance_gather.comp)
// then copies each agent's position and velocity into that order.
#include "crowd_types.h"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Counts { uint counts[]; };
layout(std430, binding = 1) readonly buffer Starts { uint starts[]; };
layout(std430, binding = 2) buffer SortedIndex { uint sortedIndex[]; };
layout(push_constant) uniform Push { GridPush push; };

// Shell sort with Ciura's gaps (extended by x2.25) rather than plain insertion sort: the
// scatter's atomic order is arbitrary, and lavapipe caps the loop iterations of one shader
// invocation at 65535 (gallivm's loop limiter), which a quadratic sort of a crowded cell
// (~400 agents) would exceed, leaving it silently unsorted.
const uint kGaps[11] = uint[11](7983u, 3548u, 1577u, 701u, 301u, 132u, 57u, 23u, 10u, 4u, 1u);

void main() {
  uint c = gl_GlobalInvocationID.x;
  if (c >= push.cellCount) return;
  uint count = counts[c];
  if (count < 2u) return;
  uint first = starts[c];
  uint end = first + count;
  uint g = 0u;
  while (kGaps[g] >= count) ++g;  // kGaps ends with 1 < count
  for (; g < 11u; ++g) {
    uint gap = kGaps[g];
    for (uint k = first + gap; k < end; ++k) {
      uint v = sortedIndex[k];
      uint j = k;
      while (j >= first + gap && sortedIndex[j - gap] > v) {
        sortedIndex[j] = sortedIndex[j - gap];
        j -= gap;
      }
      sortedIndex[j] = v;
    }
  }
}
