#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
// The far joints, step 1: one invocation per joint finds its ellipsoid's screen box and reserves
// a sprite and one pixel entry per pixel of the box for joint_splat_pixels.comp, which
// ray-casts them one pixel per invocation. A joint whose reservation does not fit ray-casts its
// own pixels here (one invocation looping over the box). Joints wider than push.maxPixels are
// listed for an indirect draw by the graphics pipeline instead. CPU twin: render::splatJointsCpu.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = kRenderBindingJoints) readonly buffer Joints { JointMatrix joints[]; };
layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(std430, binding = kRenderBindingVisibility) buffer Visibility { uint64_t visibility[]; };
layout(std430, binding = kRenderBindingDraws) buffer Draws { uint draws[]; };  // VkDrawIndirectCommand per chunk
layout(std430, binding = kRenderBindingNearList) writeonly buffer NearList { uint nearList[]; };
layout(std430, binding = kRenderBindingMasks) readonly buffer Masks { uvec4 masks[]; };  // coverage LOD, per character
layout(std430, binding = kRenderBindingGroups) readonly buffer Groups { uint groups[]; };  // kDrawGroupTint: per character
layout(push_constant) uniform Push { SplatPush push; };
#include "joint_fetch.glsl"
#include "joint_lod.glsl"
#include "joint_splat_common.glsl"
layout(std430, binding = kRenderBindingSprites) writeonly buffer Sprites { SplatSprite sprites[]; };
layout(std430, binding = kRenderBindingPixelOwners) writeonly buffer Owners { uint owners[]; };
layout(std430, binding = kRenderBindingSplatCounters) buffer Counters { SplatCounters counters; };

void main() {
  uint joint = gl_GlobalInvocationID.x;
  if (joint >= push.jointTotal) return;
  uint character = joint / push.jointCount + push.firstCharacter;
  uvec4 mask = (push.flags & (kDrawUseMasks | kDrawTintLevel)) != 0u ? masks[character] : uvec4(0xFFFFFFFFu, 0xFFFFFFFFu, 2u, 0u);
  JointMatrix a;
  if (!drawnJoint(joint, character, joint % push.jointCount, push.flags, mask, uvec2(push.boneLo, push.boneHi), a)) return;
  JointSprite s = jointSprite(a, frame);
  if (!s.visible) return;
  if (s.sizePx > push.maxPixels) {
    uint slot = atomicAdd(draws[4 * push.chunk], 1u);
    nearList[push.listBase + slot] = joint;
    return;
  }
  // Pixels whose centres lie inside the bounding box.
  ivec2 lo = max(ivec2(ceil(s.lo - 0.5)), ivec2(0));
  ivec2 hi = min(ivec2(floor(s.hi - 0.5)), ivec2(frame.viewport.xy) - 1);
  if (hi.x < lo.x || hi.y < lo.y) return;
  vec3 tint = (push.flags & kDrawTintLevel) != 0u  ? levelTint(mask.z)
              : (push.flags & kDrawGroupTint) != 0u ? groupTint(groups[character], character)
                                                    : characterTint(character);
  uint boxWidth = uint(hi.x - lo.x + 1);
  uint pixelCount = boxWidth * uint(hi.y - lo.y + 1);
  // One reservation per subgroup (its lanes' sprites and pixels summed), not two atomics per
  // joint on two shared counters: lavapipe runs a lane's atomics one at a time.
  uint spriteBase = 0u, firstBase = 0u;
  uint spriteTotal = subgroupAdd(1u), pixelTotal = subgroupAdd(pixelCount);
  if (subgroupElect()) {
    spriteBase = atomicAdd(counters.sprites, spriteTotal);
    firstBase = atomicAdd(counters.pixels, pixelTotal);
  }
  uint sprite = subgroupBroadcastFirst(spriteBase) + subgroupExclusiveAdd(1u);
  uint first = subgroupBroadcastFirst(firstBase) + subgroupExclusiveAdd(pixelCount);
  bool fits = sprite < kSpriteCapacity && first <= kPixelCapacity - min(pixelCount, kPixelCapacity);
  // Every entry reserved below the capacity gets an owner, a sentinel when the sprite is not kept.
  uint owned = first < kPixelCapacity ? min(pixelCount, kPixelCapacity - first) : 0u;
  for (uint i = 0u; i < owned; ++i) owners[first + i] = fits ? sprite : kSplatNoSprite;
  if (fits) {
    sprites[sprite] = SplatSprite(s.inverse0, s.inverse1, s.inverse2, vec4(tint, 0.0), uvec4(uint(lo.x), uint(lo.y), boxWidth, first));
    return;
  }
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) splatPixel(x, y, s.inverse0, s.inverse1, s.inverse2, tint);
}
