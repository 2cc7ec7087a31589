#version 450
#extension GL_GOOGLE_include_directive : require
// Ground with 1 m and 10 m grid lines, anti-aliased with screen-space derivatives and faded
// with distance.
#include "shared_types.h"
#include "render_bindings.h"

layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(location = 0) in vec3 worldPosition;
layout(location = 0) out vec4 color;

float gridLine(vec2 p, float spacing) {
  vec2 g = abs(fract(p / spacing - 0.5) - 0.5) / (fwidth(p / spacing) + 1e-6);
  return 1.0 - clamp(min(g.x, g.y), 0.0, 1.0);
}

void main() {
  vec2 p = worldPosition.xz;
  float fine = gridLine(p, 1.0);
  float coarse = gridLine(p, 10.0);
  float fade = exp(-length(worldPosition - frame.eye.xyz) * 0.004);
  vec3 base = vec3(0.34, 0.36, 0.33);
  vec3 c = base + fade * (0.05 * fine + 0.12 * coarse);
  color = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
