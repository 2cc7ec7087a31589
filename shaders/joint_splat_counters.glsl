// The splat's work-list capacities (specialization constants 0 and 1 of every splat shader, so
// tests can shrink them) and its counters, shared by the passes that reserve entries and the
// resolve that reads them. Needs render_bindings.h first.
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

#endif
