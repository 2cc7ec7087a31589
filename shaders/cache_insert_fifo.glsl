// The FIFO insert of one motion cache: cache_insert.comp's, and cache_insert_groups.comp's once
// per group. The includer declares the request flags `requested[]` and bucket slots
// `bucketSlot[]` (this cache's from bucketBase in both) and defines INSERT_FUNCTION (the function's
// name) and COUNTERS, SLOT_BUCKET, FRESH_SLOTS, FILL_ARGS (this cache's CacheCounters and
// arrays). CPU twin: synth::MotionCacheCpu::update.
void INSERT_FUNCTION(uint bucketBase, uint rowCount) {
  // Requested buckets already resident are hits; they and the entries inserted below are in use
  // this frame (requested = 2) and are never evicted for another bucket of the same frame: with
  // more buckets requested than the cache holds, the FIFO would otherwise refill (and the fill
  // pass re-synthesize) entries every frame, each evicting one that this frame needs.
  uint buckets = COUNTERS.bucketCount;
  for (uint b = 0u; b < buckets; ++b) {
    if (requested[bucketBase + b] == 0u || bucketSlot[bucketBase + b] < 0) continue;
    COUNTERS.hits += 1u;
    requested[bucketBase + b] = 2u;
  }
  uint fresh = 0u;
  for (uint b = 0u; b < buckets; ++b) {
    if (requested[bucketBase + b] != 1u) continue;
    COUNTERS.misses += 1u;
    if (COUNTERS.capacity == 0u) continue;
    uint slot = COUNTERS.head;
    int previous = SLOT_BUCKET[slot];
    // In use: the bucket stays uncached.
    if (previous >= 0 && requested[bucketBase + uint(previous)] != 0u) continue;
    if (previous >= 0) {
      bucketSlot[bucketBase + uint(previous)] = -1;
      COUNTERS.evictions += 1u;
    } else {
      COUNTERS.entries += 1u;
    }
    bucketSlot[bucketBase + b] = int(slot);
    SLOT_BUCKET[slot] = int(b);
    requested[bucketBase + b] = 2u;
    FRESH_SLOTS[1u + fresh] = slot;
    fresh += 1u;
    COUNTERS.head = (slot + 1u) % COUNTERS.capacity;
  }
  for (uint b = 0u; b < buckets; ++b) requested[bucketBase + b] = 0u;
  FRESH_SLOTS[0] = fresh;
  FILL_ARGS[0] = (fresh * rowCount + 63u) / 64u;
  FILL_ARGS[1] = 1u;
  FILL_ARGS[2] = 1u;
}
