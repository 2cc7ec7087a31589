#version 450
#extension GL_GOOGLE_include_directive : require
// Motion cache, step 2 (a single invocation, buckets in ascending order): each requested bucket
// is a hit when resident, else a miss that takes the FIFO head slot, evicting the oldest entry
// when the budget is full, unless that entry is in use this frame. A bucket requested by many
// characters is looked up (and synthesized) once (cache_insert_fifo.glsl).
#include "shared_types.h"
#include "synth_bindings.h"

layout(local_size_x = 1) in;
layout(std430, binding = kCacheInsertBindingCounters) buffer Counters { CacheCounters counters; };
layout(std430, binding = kCacheInsertBindingRequested) buffer Requested { uint requested[]; };
layout(std430, binding = kCacheInsertBindingBucketSlot) buffer BucketSlot { int bucketSlot[]; };
layout(std430, binding = kCacheInsertBindingSlotBucket) buffer SlotBucket { int slotBucket[]; };
// The slots inserted this frame and the indirect dispatch that fills exactly those:
// freshSlots[0] = count, freshSlots[1 …] = slots; fillArgs = VkDispatchIndirectCommand.
layout(std430, binding = kCacheInsertBindingFreshSlots) buffer FreshSlots { uint freshSlots[]; };
layout(std430, binding = kCacheInsertBindingFillArgs) writeonly buffer FillArgs { uint fillArgs[]; };
layout(push_constant) uniform Push { CachePush push; };

#define INSERT_FUNCTION insertCache
#define COUNTERS counters
#define SLOT_BUCKET slotBucket
#define FRESH_SLOTS freshSlots
#define FILL_ARGS fillArgs
#include "cache_insert_fifo.glsl"

void main() { insertCache(0u, push.rowCount); }
