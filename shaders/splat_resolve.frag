#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// One full-screen pass writes the splatted joints and the ground (the ground quad ±eye.w metres
// at y = 0, found by the pixel's ray) with their depth, the nearer of the two where both are
// hit, so the depth test composites them with the near joints and walls drawn before it. One
// pass instead of a ground draw and a resolve: on lavapipe each full-screen pass costs
// milliseconds.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"
#include "ground.glsl"

layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(std430, binding = kRenderBindingVisibility) readonly buffer Visibility { uint64_t visibility[]; };
layout(location = 0) out vec4 color;

void main() {
  vec3 eye = frame.eye.xyz;
  vec3 dir = pixelRay(gl_FragCoord.xy, frame);
  float t = dir.y < 0.0 ? -eye.y / dir.y : -1.0;
  vec3 world = eye + t * dir;
  vec4 ground = groundColour(world, eye);  // before any branch: derivatives
  vec4 clip = frame.viewProjection * vec4(world, 1.0);
  float groundDepth = clip.z / clip.w;
  bool groundHit = t > 0.0 && all(lessThanEqual(abs(world.xz), vec2(frame.eye.w))) &&
                   groundDepth >= 0.0 && groundDepth <= 1.0;

  uvec2 pixel = uvec2(gl_FragCoord.xy);
  uint64_t v = visibility[pixel.y * uint(frame.viewport.x) + pixel.x];
  float splatDepth = v == 0xFFFFFFFFFFFFFFFFul ? 2.0 : uintBitsToFloat(uint(v >> 32));
  if (groundHit && groundDepth < splatDepth) {
    gl_FragDepth = groundDepth;
    color = ground;
  } else if (splatDepth <= 1.0) {
    gl_FragDepth = splatDepth;
    color = unpackUnorm4x8(uint(v & 0xFFFFFFFFul));
  } else {
    discard;
  }
}
