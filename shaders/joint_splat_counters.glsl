// The splat's work lists: their capacities (specialization constants 0 and 1 of every splat
// shader, so tests can shrink them), their counters and their pixel entries, shared by the passes
// that reserve entries and the resolve that reads them. Needs render_bindings.h and 64-bit
// integers first.
#ifndef THRONG_JOINT_SPLAT_COUNTERS_GLSL
#define THRONG_JOINT_SPLAT_COUNTERS_GLSL

layout(constant_id = 0) const uint kSpriteCapacity = kSplatSpriteCapacity;
layout(constant_id = 1) const uint kPixelCapacity = kSplatPixelCapacity;

// Entries reserved: the sprites' pixel entries count up from the first entry, the far bodies'
// down from the last (all of a frame's bodies are reserved before any sprite), so the pixel pass
// visits the sprites' entries only.
struct SplatCounters {
  uint sprites;
  uint pixels;      // sprites' pixel entries, from entry 0 up
  uint bodyPixels;  // far bodies' hit pixels, from entry kPixelCapacity − 1 down
};

// How many entries the far bodies hold, how many the sprites may fill (the rest), and how many
// of those they hold.
uint bodyEntries(SplatCounters c) { return min(c.bodyPixels, kPixelCapacity); }
uint spriteEntryLimit(SplatCounters c) { return kPixelCapacity - bodyEntries(c); }
uint spriteEntries(SplatCounters c) { return min(c.pixels, spriteEntryLimit(c)); }

// A pixel entry (render_bindings.h): screen pixel xy and the sprite to ray-cast there (a far
// body's entry: 0; kSplatNoSprite: no entry).
uint64_t splatEntry(ivec2 xy, uint sprite) {
  return (uint64_t(uint(xy.x) | (uint(xy.y) << 16)) << 32) | uint64_t(sprite);
}
const uint64_t kSplatNoEntry = uint64_t(kSplatNoSprite);
uint entrySprite(uint64_t entry) { return uint(entry & 0xFFFFFFFFul); }
ivec2 entryPixel(uint64_t entry) {
  uint xy = uint(entry >> 32);
  return ivec2(xy & 0xFFFFu, xy >> 16);
}

#endif
