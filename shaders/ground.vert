#version 450
#extension GL_GOOGLE_include_directive : require
// A ground quad at y = 0 covering ±eye.w metres (two triangles, no vertex buffer).
#include "shared_types.h"
#include "render_bindings.h"

layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(location = 0) out vec3 worldPosition;

void main() {
  const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
  vec2 c = corners[gl_VertexIndex] * frame.eye.w;
  worldPosition = vec3(c.x, 0.0, c.y);
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
