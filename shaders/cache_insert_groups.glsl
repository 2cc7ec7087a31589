// One group's buffers and FIFO insert in cache_insert_groups.comp, included once per group with
// G its index.
#define PASTE2(a, b) a##b
#define PASTE(a, b) PASTE2(a, b)
layout(std430, binding = kCacheInsertGroupsBindingCounters + G) buffer PASTE(Counters, G) { CacheCounters PASTE(counters, G); };
layout(std430, binding = kCacheInsertGroupsBindingSlotBucket + G) buffer PASTE(SlotBucket, G) { int PASTE(slotBucket, G)[]; };
layout(std430, binding = kCacheInsertGroupsBindingFreshSlots + G) buffer PASTE(FreshSlots, G) { uint PASTE(freshSlots, G)[]; };
layout(std430, binding = kCacheInsertGroupsBindingFillArgs + G) writeonly buffer PASTE(FillArgs, G) { uint PASTE(fillArgs, G)[]; };
#define INSERT_FUNCTION PASTE(insertGroup, G)
#define COUNTERS PASTE(counters, G)
#define SLOT_BUCKET PASTE(slotBucket, G)
#define FRESH_SLOTS PASTE(freshSlots, G)
#define FILL_ARGS PASTE(fillArgs, G)
#include "cache_insert_fifo.glsl"
#undef INSERT_FUNCTION
#undef COUNTERS
#undef SLOT_BUCKET
#undef FRESH_SLOTS
#undef FILL_ARGS
