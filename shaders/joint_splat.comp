#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
// The far joints, step 1: one invocation per character walks its joints (lanes are characters
// at the same joint, so a level's undrawn joints cost its lanes nothing, and the character's
// mask, tint and pose source are read once). Each drawn joint's ellipsoid gets its screen box
// and reserves a sprite and one pixel entry per pixel of the box for joint_splat_pixels.comp,
// which ray-casts them one pixel per invocation. A far character a few pixels tall is one
// ellipsoid (joint_far_body.glsl) ray-cast here over its box, its entries naming the pixels it
// hit. A joint whose reservation does not
// fit ray-casts its own pixels here (looping over the box). Joints wider than push.maxPixels
// are listed for an indirect draw by the graphics pipeline instead. CPU twin:
// render::splatJointsCpu over render::splattedJointMatrices.
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
#include "joint_far_body.glsl"
#include "joint_splat_common.glsl"
layout(std430, binding = kRenderBindingSprites) writeonly buffer Sprites { SplatSprite sprites[]; };
layout(std430, binding = kRenderBindingPixelOwners) writeonly buffer Owners { uint owners[]; };
layout(std430, binding = kRenderBindingSplatCounters) buffer Counters { SplatCounters counters; };

// Pixels whose centres lie inside the sprite's bounding box; false when there are none.
bool spriteBox(JointSprite s, out ivec2 lo, out ivec2 hi) {
  lo = max(ivec2(ceil(s.lo - 0.5)), ivec2(0));
  hi = min(ivec2(floor(s.hi - 0.5)), ivec2(frame.viewport.xy) - 1);
  return hi.x >= lo.x && hi.y >= lo.y;
}

// One reservation per subgroup (its lanes' sprites and pixels summed), not two atomics per
// joint on two shared counters: lavapipe runs a lane's atomics one at a time. Returns the first
// pixel entry; `fits` when the sprite (if any) and every entry are below the capacities. Every
// entry reserved below the pixel capacity gets an owner, a sentinel when the entries are not kept.
uint reserveEntries(uint spriteCount, uint pixelCount, out uint sprite, out bool fits) {
  uint spriteBase = 0u, firstBase = 0u;
  uint spriteTotal = subgroupAdd(spriteCount), pixelTotal = subgroupAdd(pixelCount);
  if (subgroupElect()) {
    spriteBase = spriteTotal > 0u ? atomicAdd(counters.sprites, spriteTotal) : 0u;
    firstBase = atomicAdd(counters.pixels, pixelTotal);
  }
  sprite = subgroupBroadcastFirst(spriteBase) + subgroupExclusiveAdd(spriteCount);
  uint first = subgroupBroadcastFirst(firstBase) + subgroupExclusiveAdd(pixelCount);
  fits = (spriteCount == 0u || sprite < kSpriteCapacity) && first <= kPixelCapacity - min(pixelCount, kPixelCapacity);
  if (!fits) {
    uint owned = first < kPixelCapacity ? min(pixelCount, kPixelCapacity - first) : 0u;
    for (uint i = 0u; i < owned; ++i) owners[first + i] = kSplatNoSprite;
  }
  return first;
}

// Joint `joint` (chunk-local) as sprite s: listed for the draw when too wide, else its box's
// pixels reserved for the pixel pass (or splatted here when the work lists are full).
void splatSprite(uint joint, JointSprite s, vec3 tint) {
  if (s.sizePx > push.maxPixels) {
    uint slot = atomicAdd(draws[4 * push.chunk], 1u);
    nearList[push.listBase + slot] = joint;
    return;
  }
  ivec2 lo, hi;
  if (!spriteBox(s, lo, hi)) return;
  uint boxWidth = uint(hi.x - lo.x + 1);
  uint pixelCount = boxWidth * uint(hi.y - lo.y + 1);
  uint sprite;
  bool fits;
  uint first = reserveEntries(1u, pixelCount, sprite, fits);
  if (fits) {
    for (uint i = 0u; i < pixelCount; ++i) owners[first + i] = sprite;
    sprites[sprite] = SplatSprite(s.inverse0, s.inverse1, s.inverse2, vec4(tint, 0.0), uvec4(uint(lo.x), uint(lo.y), boxWidth, first));
    return;
  }
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) splatPixel(x, y, s.inverse0, s.inverse1, s.inverse2, tint);
}

// A far body: a few pixels, all of similar size across the lanes, so they are ray-cast here
// rather than through a sprite; their entries name the pixels hit for the resolve.
void splatBody(JointSprite s, vec3 tint) {
  ivec2 lo, hi;
  if (!spriteBox(s, lo, hi)) return;
  uint boxWidth = uint(hi.x - lo.x + 1);
  uint pixelCount = boxWidth * uint(hi.y - lo.y + 1);
  uint sprite;
  bool fits;
  uint first = reserveEntries(0u, pixelCount, sprite, fits);
  uint i = 0u;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x, ++i) {
      bool hit = splatPixel(x, y, s.inverse0, s.inverse1, s.inverse2, tint);
      if (fits) owners[first + i] = hit ? (uint(y) * uint(frame.viewport.x) + uint(x)) | kSplatPixelEntry : kSplatNoSprite;
    }
}

void main() {
  uint local = gl_GlobalInvocationID.x;  // the character within the chunk
  if (local * push.jointCount >= push.jointTotal) return;
  uint character = local + push.firstCharacter;
  uint base = local * push.jointCount;  // its first joint in the chunk
  uvec4 mask = (push.flags & (kDrawUseMasks | kDrawTintLevel)) != 0u ? masks[character] : uvec4(0xFFFFFFFFu, 0xFFFFFFFFu, 2u, 0u);
  if ((push.flags & kDrawUseMasks) != 0u && (mask.x | mask.y) == 0u) return;  // off screen
  vec3 tint = (push.flags & kDrawTintLevel) != 0u  ? levelTint(mask.z)
              : (push.flags & kDrawGroupTint) != 0u ? groupTint(groups[character], character)
                                                    : characterTint(character);
  CharacterPose pose = characterPose(character, push.flags);
  JointSprite body;
  if (farBody(pose, base, push.flags, mask, frame, body) && body.sizePx <= push.maxPixels) {
    splatBody(body, tint);
    return;
  }
  uvec2 bones = uvec2(push.boneLo, push.boneHi);
  for (uint j = 0u; j < push.jointCount; ++j) {
    JointMatrix a;
    if (!drawnPoseJoint(base + j, pose, j, push.flags, mask, bones, a)) continue;
    JointSprite s = jointSprite(a, frame);
    if (s.visible) splatSprite(base + j, s, tint);
  }
}
