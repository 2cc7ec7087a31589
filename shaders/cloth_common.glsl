// Cloth playback helpers shared by the cloth passes; mirrors engine/secondary/cloth_playback.cpp.
#include "cloth_types.h"
#include "shared_types.h"  // the motion vector's accessors
#include "speed_buckets.glsl"

// The graph tables live in one uint buffer; its first words are the offsets of each table
// (cloth_gpu.h, ClothGraphTable).
const uint kTableRunFirst = 0u;
const uint kTableRunNodes = 1u;
const uint kTableFirstSuccessor = 2u;
const uint kTableSuccessors = 3u;
const uint kTableFirstEdge = 4u;
const uint kTableEdgeTarget = 5u;
const uint kTableEdgeIsMerge = 6u;
const uint kTableFirstStateAtNode = 7u;
const uint kTableNaturalSuccessor = 8u;

// Rotation about +y by `heading` (the yaw quaternion of the synthesis) applied to p.
vec3 clothRotateY(float heading, vec3 p) {
  float c = cos(heading), s = sin(heading);
  return vec3(c * p.x + s * p.z, p.y, -s * p.x + c * p.z);
}

// Twins: secondary::shownState and showsBlend (need the Graph buffer declared as `graph`).
#ifdef CLOTH_HAS_GRAPH
uint clothShownState(ClothCharacter c, uint level) {
  if (level < kClothSharedLevel) return c.state;
  uint first = graph[graph[kTableFirstStateAtNode] + c.node];
  return first == kClothNone ? c.state : first;
}
#endif
bool clothShowsBlend(ClothCharacter c, uint level) {
  return level < kClothSharedLevel && c.countdown > 0u && c.blendSource != kClothNone;
}

// A cape's colour: a dark red varied per character, or its level (green, yellow, orange, red).
vec3 clothTint(uint character) {
  uint h = character * 747796405u + 2891336453u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  vec3 random = vec3(float(h & 255u), float((h >> 8) & 255u), float((h >> 16) & 255u)) / 255.0;
  return mix(vec3(0.55, 0.1, 0.12), random, 0.35);
}
vec3 clothLevelTint(uint level) {
  const vec3 tints[4] = vec3[4](vec3(0.2, 0.75, 0.3), vec3(0.95, 0.8, 0.2), vec3(0.95, 0.5, 0.15), vec3(0.9, 0.2, 0.2));
  return tints[min(level, 3u)];
}
