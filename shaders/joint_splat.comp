#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
// The far joints, step 1: one invocation per character on screen (joint_splat_list.comp's list,
// dispatched by its length). A far character a few pixels tall is one ellipsoid
// (joint_far_body.glsl) ray-cast here over its box, an atomicMin on each pixel it hits;
// every other character is listed for joint_splat_walk.comp, which walks its joints, so that
// lanes walking joints are not spread over subgroups of bodies. CPU twin: render::splatJointsCpu
// over render::splattedJointMatrices.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"

layout(local_size_x = kSplatBodyGroupSize) in;
layout(std430, binding = kRenderBindingJoints) readonly buffer Joints { JointPoint joints[]; };
// Copied at the top of main, as in joint_splat_walk.comp (lavapipe reads uniforms inside
// branches and loops lane by lane).
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
layout(std430, binding = kRenderBindingWalkList) writeonly buffer WalkList { uint walkList[]; };
layout(std430, binding = kRenderBindingListCounts) buffer ListCounts { uint listCounts[]; };
layout(std430, binding = kRenderBindingOnScreenList) readonly buffer OnScreenList { uint onScreenList[]; };

void main() {
  frame = frameBlock;
  push = pushBlock;
  uint k = gl_GlobalInvocationID.x;
  if (k >= listCounts[kSplatListArgsWords * push.chunk + kSplatOnScreenArgs]) return;
  uint local = onScreenList[push.firstCharacter + k];  // the character within the chunk
  uint character = local + push.firstCharacter;
  uvec4 mask = characterMask(character);
  JointSprite body;
  bool walks = true;
  if (farBody(characterPose(character, push.flags), local * push.jointCount, push.flags, mask, frame, body) &&
      body.sizePx <= push.maxPixels) {
    splatBody(body, characterColour(character, mask));
    walks = false;
  }
  if (walks) {  // one atomic per subgroup, and the walk's workgroups grown to cover the list
    uint at = 0u, total = subgroupAdd(1u);
    uint args = kSplatListArgsWords * push.chunk + kSplatWalkArgs;
    if (subgroupElect()) {
      at = atomicAdd(listCounts[args], total);
      uint groups = (at + total + kSplatWalkGroupSize - 1u) / kSplatWalkGroupSize;
      atomicMax(listCounts[args + 1u], groups);
    }
    walkList[push.firstCharacter + subgroupBroadcastFirst(at) + subgroupExclusiveAdd(1u)] = local;
  }
}
