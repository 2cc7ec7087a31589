#version 450
#extension GL_GOOGLE_include_directive : require
// Counting sort, pass 2: exclusive prefix sum of the cell counts, starts[c] = first slot of
// cell c, starts[cellCount] = the agent count. One workgroup: each thread sums a run of
// cellCount / kScanThreads cells, the run totals are scanned in shared memory, then each thread
// writes its run. On lavapipe a workgroup is one thread's loop, so this single pass (two
// barriers) beats a multi-pass tree scan whose cost is in the passes and barriers.
#include "crowd_types.h"

layout(local_size_x = 256) in;
layout(std430, binding = 0) readonly buffer Counts { uint counts[]; };
layout(std430, binding = 1) writeonly buffer Starts { uint starts[]; };
layout(push_constant) uniform Push { GridPush push; };

shared uint runTotal[kScanThreads];

void main() {
  uint t = gl_LocalInvocationID.x;
  uint per = (push.cellCount + kScanThreads - 1u) / kScanThreads;
  uint first = min(t * per, push.cellCount);
  uint end = min(first + per, push.cellCount);
  uint sum = 0u;
  for (uint c = first; c < end; ++c) sum += counts[c];
  runTotal[t] = sum;
  barrier();
  uint before = 0u;
  for (uint k = 0u; k < t; ++k) before += runTotal[k];
  for (uint c = first; c < end; ++c) {
    starts[c] = before;
    before += counts[c];
  }
  if (t == kScanThreads - 1u) starts[push.cellCount] = before;
}
