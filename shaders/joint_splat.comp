#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
// The far joints: one invocation per joint ray-casts its ellipsoid over the pixels of its small
// screen square and keeps the nearest hit per pixel with a 64-bit atomicMin of
// (depth bits << 32 | colour). Joints wider than push.maxPixels are listed for an indirect
// draw by the graphics pipeline instead. CPU twin: render::splatJointsCpu.
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
  vec3 tint = (push.flags & kDrawTintLevel) != 0u  ? levelTint(mask.z)
              : (push.flags & kDrawGroupTint) != 0u ? groupTint(groups[character], character)
                                                    : characterTint(character);
  uint width = uint(frame.viewport.x);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      vec3 dir = pixelRay(vec2(x, y) + 0.5, frame);
      float t;
      vec3 n;
      if (!hitJoint(frame.eye.xyz, dir, s.inverse0, s.inverse1, s.inverse2, t, n)) continue;
      vec4 clip = frame.viewProjection * vec4(frame.eye.xyz + t * dir, 1.0);
      float depth = clip.z / clip.w;
      if (depth < 0.0 || depth > 1.0) continue;
      uint colour = packUnorm4x8(vec4(shadeJoint(tint, n, dir, frame.lightDirection.xyz), 1.0));
      uint64_t packed = (uint64_t(floatBitsToUint(depth)) << 32) | uint64_t(colour);
      atomicMin(visibility[uint(y) * width + uint(x)], packed);
    }
  }
}
