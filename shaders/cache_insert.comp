#version 450
#extension GL_GOOGLE_include_directive : require
// Motion cache, step 2 (a single invocation, buckets in ascending order): each requested bucket
// is a hit when resident, else a miss that takes the FIFO head slot, evicting the oldest entry
// when the budget is full, unless that entry is in use this frame. A bucket requested by many characters is looked up (and synthesized)
// once. CPU twin: synth::MotionCacheCpu::update.
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

void main() {
  // Requested buckets already resident are hits; they and the entries inserted below are in use
  // this frame (requested = 2) and are never evicted for another bucket of the same frame: with
  // more buckets requested than the cache holds, the FIFO would otherwise refill (and the fill
  // pass re-synthesize) entries every frame, each evicting one that this frame needs.
  for (uint b = 0u; b < counters.bucketCount; ++b) {
    if (requested[b] == 0u || bucketSlot[b] < 0) continue;
    counters.hits += 1u;
    requested[b] = 2u;
  }
  uint fresh = 0u;
  for (uint b = 0u; b < counters.bucketCount; ++b) {
    if (requested[b] != 1u) continue;
    counters.misses += 1u;
    if (counters.capacity == 0u) continue;
    uint slot = counters.head;
    int previous = slotBucket[slot];
    if (previous >= 0 && requested[previous] != 0u) continue;  // in use: the bucket stays uncached
    if (previous >= 0) {
      bucketSlot[previous] = -1;
      counters.evictions += 1u;
    } else {
      counters.entries += 1u;
    }
    bucketSlot[b] = int(slot);
    slotBucket[slot] = int(b);
    requested[b] = 2u;
    freshSlots[1u + fresh] = slot;
    fresh += 1u;
    counters.head = (slot + 1u) % counters.capacity;
  }
  for (uint b = 0u; b < counters.bucketCount; ++b) requested[b] = 0u;
  freshSlots[0] = fresh;
  fillArgs[0] = (fresh * push.rowCount + 63u) / 64u;
  fillArgs[1] = 1u;
  fillArgs[2] = 1u;
}
