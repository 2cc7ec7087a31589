#version 450
#extension GL_GOOGLE_include_directive : require
// Counting sort, pass 2c: add each block's offset, so starts[c] is the first slot of cell c.
#include "crowd_types.h"

layout(local_size_x = 256) in;
layout(std430, binding = 0) buffer Starts { uint starts[]; };
layout(std430, binding = 1) readonly buffer BlockSums { uint blockSums[]; };
layout(push_constant) uniform Push { GridPush push; };

void main() {
  uint c = gl_GlobalInvocationID.x;
  if (c >= push.cellCount) return;
  starts[c] += blockSums[c / kScanBlock];
}
