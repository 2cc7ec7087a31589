#version 450
#extension GL_GOOGLE_include_directive : require
// Motion cache, step 2 for every group of a crowd in one dispatch (a single invocation, group
// by group): each group's FIFO insert (cache_insert_fifo.glsl) on its own counters, slots and
// fill arguments, its request flags and bucket slots in the shared buffers from its bases in
// the group table. Unused groups' bindings hold stand-ins that are never touched.
#include "shared_types.h"
#include "synth_bindings.h"

layout(local_size_x = 1) in;
layout(std430, binding = kCacheInsertGroupsBindingRequested) buffer Requested { uint requested[]; };
layout(std430, binding = kCacheInsertGroupsBindingBucketSlot) buffer BucketSlot { int bucketSlot[]; };
layout(std140, binding = kCacheInsertGroupsBindingGroups) uniform Groups { SynthGroupTable table; };

#define G 0
#include "cache_insert_groups.glsl"
#undef G
#define G 1
#include "cache_insert_groups.glsl"
#undef G
#define G 2
#include "cache_insert_groups.glsl"
#undef G
#define G 3
#include "cache_insert_groups.glsl"
#undef G

void main() {
  uint groups = table.counts.x;
  insertGroup0(table.groups[0].bucketBase, table.groups[0].cacheRowCount);
  if (groups > 1u) insertGroup1(table.groups[1].bucketBase, table.groups[1].cacheRowCount);
  if (groups > 2u) insertGroup2(table.groups[2].bucketBase, table.groups[2].cacheRowCount);
  if (groups > 3u) insertGroup3(table.groups[3].bucketBase, table.groups[3].cacheRowCount);
}
