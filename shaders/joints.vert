#version 450
#extension GL_GOOGLE_include_directive : require
// The near joints: one point sprite per joint (one non-instanced point-list draw) covering its
// ellipsoid on screen; the fragment shader ray-casts the ellipsoid exactly. With the compute
// splat on, the draw is indirect over the list of joints the splat found too wide for it
// (joint_splat.comp), so tiny far joints never reach lavapipe's single-threaded vertex path.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"

layout(std430, binding = kRenderBindingJoints) readonly buffer Joints { JointPoint joints[]; };
layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(std430, binding = kRenderBindingNearList) readonly buffer NearList { uint nearList[]; };
layout(std430, binding = kRenderBindingMasks) readonly buffer Masks { uvec4 masks[]; };  // coverage LOD, per character
layout(std430, binding = kRenderBindingGroups) readonly buffer Groups { uint groups[]; };  // kDrawGroupTint: per character
layout(push_constant) uniform Push { DrawPush push; };
#include "joint_fetch.glsl"
#include "joint_lod.glsl"

layout(location = 0) flat out vec3 tint;
layout(location = 1) flat out vec4 inverse0;
layout(location = 2) flat out vec4 inverse1;
layout(location = 3) flat out vec4 inverse2;

void main() {
  uint joint = (push.flags & kDrawFromList) != 0u ? nearList[push.listBase + uint(gl_VertexIndex)] : uint(gl_VertexIndex);
  uint character = joint / push.jointCount + push.firstCharacter;
  uvec4 mask = (push.flags & (kDrawUseMasks | kDrawTintLevel)) != 0u ? masks[character] : uvec4(0xFFFFFFFFu, 0xFFFFFFFFu, 2u, 0u);
  JointMatrix a;
  bool drawn = drawnJoint(joint, character, joint % push.jointCount, push.flags, mask, uvec2(push.boneLo, push.boneHi), a);
  JointSprite s = jointSprite(a, frame);
  if (!drawn || !s.visible) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume
    gl_PointSize = 1.0;
    return;
  }
  inverse0 = s.inverse0;
  inverse1 = s.inverse1;
  inverse2 = s.inverse2;
  tint = (push.flags & kDrawTintLevel) != 0u  ? levelTint(mask.z)
         : (push.flags & kDrawGroupTint) != 0u ? groupTint(groups[character], character)
                                               : characterTint(character);
  // The sprite is centred on the bounding box (not on the projected centre) so it covers it.
  vec2 boxCentreNdc = (s.lo + s.hi) / frame.viewport.xy - 1.0;
  gl_PointSize = min(s.sizePx, 255.0);
  gl_Position = vec4(boxCentreNdc * s.clip.w, s.clip.z, s.clip.w);
}
