#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// Writes the splatted joints into the frame with their depth, so the depth test composites
// them with the ground and the near joints.
#include "shared_types.h"
#include "render_bindings.h"

layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(std430, binding = kRenderBindingVisibility) readonly buffer Visibility { uint64_t visibility[]; };
layout(location = 0) out vec4 color;

void main() {
  uvec2 pixel = uvec2(gl_FragCoord.xy);
  uint64_t v = visibility[pixel.y * uint(frame.viewport.x) + pixel.x];
  if (v == 0xFFFFFFFFFFFFFFFFul) discard;
  gl_FragDepth = uintBitsToFloat(uint(v >> 32));
  color = unpackUnorm4x8(uint(v & 0xFFFFFFFFul));
}
