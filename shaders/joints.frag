#version 450
#extension GL_GOOGLE_include_directive : require
// Ray-casts the joint's ellipsoid through this pixel, writes its true depth, and shades it.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"

layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(location = 0) flat in vec3 tint;
layout(location = 1) flat in vec4 inverse0;
layout(location = 2) flat in vec4 inverse1;
layout(location = 3) flat in vec4 inverse2;
layout(location = 0) out vec4 color;

void main() {
  vec3 dir = pixelRay(gl_FragCoord.xy, frame);
  float t;
  vec3 n;
  if (!hitJoint(frame.eye.xyz, dir, inverse0, inverse1, inverse2, t, n)) discard;
  vec4 clip = frame.viewProjection * vec4(frame.eye.xyz + t * dir, 1.0);
  gl_FragDepth = clip.z / clip.w;
  color = vec4(shadeJoint(tint, n, dir, frame.lightDirection.xyz), 1.0);
}
