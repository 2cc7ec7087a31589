#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Counting sort, pass 2: exclusive prefix sum of the cell counts, starts[c] = first slot of
// cell c, starts[cellCount] = the agent count. One workgroup: each thread sums a run of
// cellCount / kScanThreads cells, the run totals are scanned in shared memory, then each thread
// writes its run. On lavapipe a workgroup is one thread's loop, so this single pass (two
// barriers) beats a multi-pass tree scan whose cost is in the passes and barriers.
#include "crowd_types.h"

layout(local_size_x = 256) in;
// Four counts per 64-bit pair: lavapipe moves a vector one component per lane at a time. The
// table has a power-of-two number of cells, at least 4 per thread.
layout(std430, binding = 0) readonly buffer Counts { u64vec2 counts[]; };
layout(std430, binding = 1) writeonly buffer Starts { u64vec2 starts[]; };
layout(std430, binding = 1) writeonly buffer StartsEnd { uint startsEnd[]; };
layout(push_constant) uniform Push { GridPush push; };

shared uint runTotal[kScanThreads];

uvec4 unpackCounts(u64vec2 w) { return uvec4(unpackUint2x32(w.x), unpackUint2x32(w.y)); }

void main() {
  uint t = gl_LocalInvocationID.x;
  uint per = push.cellCount / (4u * kScanThreads);  // 64-bit pairs per thread
  uint first = t * per;
  uint end = first + per;
  uint sum = 0u;
  for (uint q = first; q < end; ++q) {
    uvec4 c = unpackCounts(counts[q]);
    sum += c.x + c.y + c.z + c.w;
  }
  runTotal[t] = sum;
  barrier();
  uint before = 0u;
  for (uint k = 0u; k < t; ++k) before += runTotal[k];
  for (uint q = first; q < end; ++q) {
    uvec4 c = unpackCounts(counts[q]);
    uvec4 s = uvec4(before, before + c.x, before + c.x + c.y, before + c.x + c.y + c.z);
    starts[q] = u64vec2(packUint2x32(s.xy), packUint2x32(s.zw));
    before = s.w + c.w;
  }
  if (t == kScanThreads - 1u) startsEnd[push.cellCount] = before;
}
