#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
// The far joints, step 2: the characters joint_splat.comp listed have their joints walked. Each
// drawn joint's ellipsoid gets its screen box and the pixels of its silhouette. Dispatched
// indirectly with as many workgroups as the list needs, one invocation per listed character, in
// one row or in a row per joint (render::SplatWalk, specialization constant 3):
// - in one row (lavapipe's way) an invocation walks its character's joints and ray-casts each
//   joint's pixels itself (lanes are characters at the same joint, so a level's undrawn joints
//   cost its lanes nothing, and the character's mask, tint and pose source are read once);
// - in row y (a GPU's way: many short threads) it takes joint y alone and reserves a sprite and
//   one pixel entry per pixel for joint_splat_pixels.comp, which ray-casts them one pixel per
//   invocation.
// Joints wider than push.maxPixels, and (per joint) joints whose reservation does not fit, are
// listed for an indirect draw by the graphics pipeline instead.
// CPU twin: render::splatJointsCpu over render::splattedJointMatrices.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"

layout(local_size_x = kSplatWalkGroupSize) in;
layout(std430, binding = kRenderBindingJoints) readonly buffer Joints { JointPoint joints[]; };
// The frame's uniforms and the push constants, copied at the top of main: lavapipe reads a
// uniform inside a branch or loop lane by lane (it cannot tell that the first lane is active
// there), and nearly everything here is inside one; read before any, each is one load.
layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frameBlock; };
FrameUniforms frame;
layout(std430, binding = kRenderBindingVisibility) buffer Visibility { uint64_t visibility[]; };
layout(std430, binding = kRenderBindingDraws) buffer Draws { uint draws[]; };  // VkDrawIndirectCommand per chunk
layout(std430, binding = kRenderBindingNearList) writeonly buffer NearList { uint nearList[]; };
layout(std430, binding = kRenderBindingMasks) readonly buffer Masks { uvec4 masks[]; };  // coverage LOD, per character
layout(std430, binding = kRenderBindingGroups) readonly buffer Groups { uint groups[]; };  // kDrawGroupTint: per character
layout(push_constant) uniform Push { SplatPush pushBlock; };
SplatPush push;
#include "joint_fetch.glsl"
#include "joint_lod.glsl"
#include "joint_far_body.glsl"
#include "joint_splat_common.glsl"
layout(std430, binding = kRenderBindingSprites) writeonly buffer Sprites { SplatSprite sprites[]; };
layout(std430, binding = kRenderBindingPixelOwners) writeonly buffer Owners { uint64_t owners[]; };
layout(std430, binding = kRenderBindingSplatCounters) buffer Counters { SplatCounters counters; };
#include "joint_splat_reserve.glsl"
layout(std430, binding = kRenderBindingWalkList) readonly buffer WalkList { uint walkList[]; };
layout(std430, binding = kRenderBindingListCounts) readonly buffer ListCounts { uint listCounts[]; };

// Joints first..end-1 of chunk-local character `local`.
void walkJoints(uint local, uint first, uint end) {
  uint character = local + push.firstCharacter;
  uint base = local * push.jointCount;  // its first joint in the chunk
  uvec4 mask = characterMask(character);
  vec3 tint = characterColour(character, mask);
  CharacterPose pose = characterPose(character, push.flags);
  uvec2 bones = uvec2(push.boneLo, push.boneHi);
  FrameRays rays = frameRays();  // once per character, not per joint
  for (uint j = first; j < end; ++j) {
    JointMatrix a;
    if (!drawnPoseJoint(base + j, pose, j, push.flags, mask, bones, a)) continue;
    JointSprite s = jointSprite(a, frame);
    if (s.visible) splatSprite(base + j, s, tint, rays);
  }
}

void main() {
  frame = frameBlock;
  push = pushBlock;
  uint k = gl_GlobalInvocationID.x;
  if (k >= listCounts[kSplatListArgsWords * push.chunk + kSplatWalkArgs]) return;
  bool perJoint = gl_NumWorkGroups.y > 1u;  // a row per joint (one joint: the same either way)
  uint first = perJoint ? gl_WorkGroupID.y : 0u;
  uint end = perJoint ? first + 1u : push.jointCount;
  walkJoints(walkList[push.firstCharacter + k], first, end);
}
