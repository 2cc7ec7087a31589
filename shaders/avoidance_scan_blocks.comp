#version 450
#extension GL_GOOGLE_include_directive : require
// Counting sort, pass 2a: exclusive prefix sum of the cell counts within blocks of kScanBlock
// cells (256 threads × 4 cells), and each block's total for pass 2b.
#include "crowd_types.h"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly buffer Counts { uint counts[]; };
layout(std430, binding = 1) writeonly buffer Starts { uint starts[]; };
layout(std430, binding = 2) writeonly buffer BlockSums { uint blockSums[]; };
layout(push_constant) uniform Push { GridPush push; };

shared uint partial[256];

void main() {
  uint t = gl_LocalInvocationID.x;
  uint base = gl_WorkGroupID.x * kScanBlock + t * 4u;
  uint v[4];
  uint sum = 0u;
  for (uint k = 0u; k < 4u; ++k) {
    uint c = base + k < push.cellCount ? counts[base + k] : 0u;
    v[k] = sum;
    sum += c;
  }
  partial[t] = sum;
  barrier();
  // Hillis–Steele inclusive scan of the 256 thread totals.
  for (uint offset = 1u; offset < 256u; offset <<= 1u) {
    uint add = t >= offset ? partial[t - offset] : 0u;
    barrier();
    partial[t] += add;
    barrier();
  }
  uint before = t > 0u ? partial[t - 1u] : 0u;
  for (uint k = 0u; k < 4u; ++k)
    if (base + k < push.cellCount) starts[base + k] = before + v[k];
  if (t == 255u) blockSums[gl_WorkGroupID.x] = partial[255];
}
