#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// The splat and the ground into a target that takes no copies (the viewer's swapchain): one
// full-screen pass shades the ground (the quad ±eye.w metres at y = 0, found by the pixel's ray)
// and writes the nearer of it and the pixel's splat hit with its depth, so the depth test
// composites both with the walls and the near joints. A target that takes copies gets the same
// picture from visibility_planes.comp instead.
#include "shared_types.h"
#include "render_bindings.h"
#include "joint_sprite.glsl"
#include "ground.glsl"

layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(std430, binding = kRenderBindingVisibility) readonly buffer Visibility { uint64_t visibility[]; };
layout(location = 0) out vec4 color;

void main() {
  vec3 eye = frame.eye.xyz;
  float t;
  vec3 world = groundPoint(eye, pixelRay(gl_FragCoord.xy, frame), t);
  vec4 ground = groundColour(world, fwidth(world.xz), eye);  // before any branch: derivatives
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
