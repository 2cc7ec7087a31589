#version 450
#extension GL_GOOGLE_include_directive : require
// Counting sort, pass 2b: exclusive prefix sum of the block totals, in place, by one
// workgroup (256 threads × 4 blocks: up to 1024 blocks of kScanBlock cells).
#include "crowd_types.h"

layout(local_size_x = 256) in;
layout(std430, binding = 0) buffer BlockSums { uint blockSums[]; };
layout(push_constant) uniform Push { GridPush push; };

shared uint partial[256];

void main() {
  uint t = gl_LocalInvocationID.x;
  uint base = t * 4u;
  uint v[4];
  uint sum = 0u;
  for (uint k = 0u; k < 4u; ++k) {
    uint c = base + k < push.blockCount ? blockSums[base + k] : 0u;
    v[k] = sum;
    sum += c;
  }
  partial[t] = sum;
  barrier();
  for (uint offset = 1u; offset < 256u; offset <<= 1u) {
    uint add = t >= offset ? partial[t - offset] : 0u;
    barrier();
    partial[t] += add;
    barrier();
  }
  uint before = t > 0u ? partial[t - 1u] : 0u;
  for (uint k = 0u; k < 4u; ++k)
    if (base + k < push.blockCount) blockSums[base + k] = before + v[k];
}
