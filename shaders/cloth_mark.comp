#version 450
#extension GL_GOOGLE_include_directive : require
// Cloth playback, pass 2: per character, cull its cape and pick a level from its size on screen,
// mark the states it shows (its state, and the blend source while blending) with the finest level
// any character needs, list each used state once, and append the character to its level's draw.
#include "cloth_types.h"
#include "cloth_bindings.h"

layout(local_size_x = 64) in;
layout(std140, binding = kClothMarkBindingView) uniform View { ClothView view; };
layout(std430, binding = kClothMarkBindingCharacters) readonly buffer Characters { ClothCharacter characters[]; };
layout(std430, binding = kClothMarkBindingPlacement) readonly buffer Placement { vec4 placement[]; };  // (x, y, z, heading)
layout(std430, binding = kClothMarkBindingMotion) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = kClothMarkBindingCounters) buffer Counters { ClothCounters counters; };
layout(std430, binding = kClothMarkBindingStateLevel) buffer StateLevel { uint stateLevel[]; };
layout(std430, binding = kClothMarkBindingUsedStates) writeonly buffer UsedStates { uint usedStates[]; };
layout(std430, binding = kClothMarkBindingDraws) buffer Draws { uint draws[]; };  // VkDrawIndexedIndirectCommand per level
layout(std430, binding = kClothMarkBindingDrawList) writeonly buffer DrawList { uint drawList[]; };
layout(std430, binding = kClothMarkBindingGraph) readonly buffer Graph { uint graph[]; };
#define CLOTH_HAS_GRAPH
#include "cloth_common.glsl"
layout(push_constant) uniform Push { ClothMarkPush push; };

void markState(uint state, uint level) {
  uint previous = atomicMin(stateLevel[state], level);
  if (previous == kClothNone) {
    uint u = atomicAdd(counters.usedStates, 1u);
    if (u < push.maxUsedStates) usedStates[u] = state;
  }
}

// Twin: secondary::clothLevel.
uint clothLevel(vec4 place, float scale) {
  vec3 centre = place.xyz + clothRotateY(place.w, scale * view.bounds.xyz);
  float radius = scale * view.bounds.w;
  for (uint p = 0u; p < 6u; ++p)
    if (dot(view.planes[p].xyz, centre) + view.planes[p].w < -radius) return kClothNone;
  if (view.lod.w == 0.0) return 0u;
  float distance = max(length(centre - view.eye.xyz), 1e-3);
  float diameter = 2.0 * view.eye.w * scale * view.light.w / distance;
  return diameter >= view.lod.x ? 0u : (diameter >= view.lod.y ? 1u : (diameter >= view.lod.z ? 2u : 3u));
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.characterCount) return;
  ClothCharacter c = characters[i];
  if (c.state == kClothNone) return;
  uint level = clothLevel(placement[i], characterScale(motion[i]));
  if (level == kClothNone) return;
  markState(clothShownState(c, level), level);
  if (clothShowsBlend(c, level)) markState(c.blendSource, level);
  uint slot = atomicAdd(draws[5u * level + 1u], 1u);  // instanceCount
  drawList[level * push.characterCount + slot] = i;
}
