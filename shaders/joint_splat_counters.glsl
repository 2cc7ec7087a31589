// The splat's work lists: their capacities (specialization constants 0 and 1 of every splat
// shader, so tests can shrink them), their counters and their pixel entries, shared by the walk
// that reserves entries and the pixel pass that reads them. Needs render_bindings.h and 64-bit
// integers first.
#ifndef THRONG_JOINT_SPLAT_COUNTERS_GLSL
#define THRONG_JOINT_SPLAT_COUNTERS_GLSL

layout(constant_id = 0) const uint kSpriteCapacity = kSplatSpriteCapacity;
layout(constant_id = 1) const uint kPixelCapacity = kSplatPixelCapacity;

// Sprites and pixel entries reserved (the far bodies reserve none: they write their pixels
// themselves).
struct SplatCounters {
  uint sprites;
  uint pixels;
};

// The entries the pixel pass visits: those reserved, up to the capacity.
uint spriteEntries(SplatCounters c) { return min(c.pixels, kPixelCapacity); }

// A pixel entry (render_bindings.h): screen pixel xy and the sprite to ray-cast there
// (kSplatNoSprite: no entry).
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
