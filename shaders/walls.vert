#version 450
#extension GL_GOOGLE_include_directive : require
// Static walls as vertical panels: six vertices per segment (two triangles from the ground to
// kWallHeight), no vertex buffer; the segments are the avoidance's own (crowd::WallBuffers).
#include "shared_types.h"
#include "render_bindings.h"

const float kWallHeight = 1.2;  // metres: low enough to see the crowd over, high enough to read

layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(binding = kRenderBindingWalls) uniform samplerBuffer segments;
layout(location = 0) out vec3 worldPosition;
layout(location = 1) flat out vec3 normal;

void main() {
  const vec2 corners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
  vec4 s = texelFetch(segments, gl_VertexIndex / 6);
  vec2 c = corners[gl_VertexIndex % 6];
  vec2 ground = mix(s.xy, s.zw, c.x);
  worldPosition = vec3(ground.x, c.y * kWallHeight, ground.y);
  vec2 d = s.zw - s.xy;
  normal = normalize(vec3(-d.y, 0.0, d.x) + vec3(0.0, 1e-6, 0.0));
  gl_Position = frame.viewProjection * vec4(worldPosition, 1.0);
}
