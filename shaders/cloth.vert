#version 450
#extension GL_GOOGLE_include_directive : require
// Cloth playback, draw: instance i is character drawList[i] at level i / characterCount (each
// level is one indexed indirect draw whose firstInstance is level × characterCount); vertex k is
// position k of the coarse-first order, read from the decoded slot of the state the character
// shows at that level (remapped to a coarser representative when the state was decoded coarser),
// blended with the merge source, and placed on the character's root (x, y, z, heading, scale).
#include "cloth_types.h"
#include "cloth_bindings.h"

layout(std140, binding = kClothDrawBindingView) uniform View { ClothView view; };
layout(std430, binding = kClothDrawBindingCharacters) readonly buffer Characters { ClothCharacter characters[]; };
layout(std430, binding = kClothDrawBindingPlacement) readonly buffer Placement { vec4 placement[]; };
layout(std430, binding = kClothDrawBindingMotion) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = kClothDrawBindingDrawList) readonly buffer DrawList { uint drawList[]; };
layout(std430, binding = kClothDrawBindingSlots) readonly buffer Slots { uvec2 slots[]; };
layout(std430, binding = kClothDrawBindingPool) readonly buffer Pool { float pool[]; };
layout(std430, binding = kClothDrawBindingRemap) readonly buffer Remap { uint remap[]; };
layout(std430, binding = kClothDrawBindingGraph) readonly buffer Graph { uint graph[]; };
#define CLOTH_HAS_GRAPH
#include "cloth_common.glsl"
layout(push_constant) uniform Push { ClothDrawPush push; };

layout(location = 0) out vec3 worldPosition;
layout(location = 1) flat out vec3 tint;

vec3 fetchVertex(uint state, uint k, uint level) {
  uvec2 slot = slots[state];
  if (slot.y > level) k = remap[slot.y * push.vertexCount + k];
  uint o = 3u * (slot.x + k);
  return vec3(pool[o], pool[o + 1u], pool[o + 2u]);
}

void main() {
  uint instance = uint(gl_InstanceIndex);
  uint level = instance / push.characterCount;
  uint character = drawList[instance];
  ClothCharacter c = characters[character];
  uint k = uint(gl_VertexIndex);
  vec3 p = fetchVertex(clothShownState(c, level), k, level);
  if (clothShowsBlend(c, level))
    p = mix(p, fetchVertex(c.blendSource, k, level), float(c.countdown) / float(push.blendFrames + 1u));
  vec4 place = placement[character];
  worldPosition = place.xyz + clothRotateY(place.w, characterScale(motion[character]) * p);
  gl_Position = view.viewProjection * vec4(worldPosition, 1.0);
  tint = (push.flags & kClothDrawTint) != 0u ? clothLevelTint(level) : clothTint(character);
}
