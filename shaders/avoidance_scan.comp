#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_shuffle : require
// Counting sort, pass 2: exclusive prefix sum of the cell counts, starts[c] = first slot of
// cell c, starts[cellCount] = the agent count. One workgroup: each thread sums a run of
// cellCount / kScanThreads cells, the run totals are scanned (by shuffles within a subgroup,
// then over the subgroups' totals in shared memory), then each thread writes its run. On
// lavapipe a workgroup is one thread's loop, so this single pass (one barrier) beats a
// multi-pass tree scan whose cost is in the passes and barriers.
#include "crowd_types.h"
#include "crowd_bindings.h"

layout(local_size_x = 256) in;
// Four counts per texel (read with one gather for all lanes on lavapipe, where a storage load
// loops over them), four starts per 64-bit pair. The table has a power-of-two number of cells,
// at least 4 per thread.
layout(binding = kGridScanBindingCounts) uniform usamplerBuffer countTexels;
layout(std430, binding = kGridScanBindingStarts) writeonly buffer Starts { u64vec2 starts[]; };
layout(std430, binding = kGridScanBindingStarts) writeonly buffer StartsEnd { uint startsEnd[]; };
layout(push_constant) uniform Push { GridPush push; };

shared uint subgroupTotal[kScanThreads];

void main() {
  uint cellCount = push.cellCount;
  uint t = gl_LocalInvocationID.x;
  uint per = cellCount / (4u * kScanThreads);  // texels (4 cells) per thread
  uint first = t * per;
  uint end = first + per;
  uint sum = 0u;
  for (uint q = first; q < end; ++q) {
    uvec4 c = texelFetch(countTexels, int(q));
    sum += c.x + c.y + c.z + c.w;
  }
  // Inclusive scan of the run totals within the subgroup (Hillis-Steele by shuffles), then the
  // totals of the subgroups before this one.
  uint lane = gl_SubgroupInvocationID;
  uint inclusive = sum;
  for (uint d = 1u; d < gl_SubgroupSize; d <<= 1u) {
    uint below = subgroupShuffle(inclusive, lane >= d ? lane - d : lane);
    inclusive += lane >= d ? below : 0u;
  }
  if (lane == gl_SubgroupSize - 1u) subgroupTotal[gl_SubgroupID] = inclusive;
  barrier();
  uint before = inclusive - sum;
  for (uint k = 0u; k < gl_SubgroupID; ++k) before += subgroupTotal[k];
  for (uint q = first; q < end; ++q) {
    uvec4 c = texelFetch(countTexels, int(q));
    uvec4 s = uvec4(before, before + c.x, before + c.x + c.y, before + c.x + c.y + c.z);
    starts[q] = u64vec2(packUint2x32(s.xy), packUint2x32(s.zw));
    before = s.w + c.w;
  }
  if (t == kScanThreads - 1u) startsEnd[cellCount] = before;
}
