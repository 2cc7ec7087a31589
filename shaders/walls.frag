#version 450
#extension GL_GOOGLE_include_directive : require
// A wall panel: a light warm grey, lit from the frame's light on either side, darker towards
// the ground so panels read as standing on it.
#include "shared_types.h"
#include "render_bindings.h"

layout(std140, binding = kRenderBindingFrame) uniform Frame { FrameUniforms frame; };
layout(location = 0) in vec3 worldPosition;
layout(location = 1) flat in vec3 normal;
layout(location = 0) out vec4 color;

void main() {
  float light = 0.55 + 0.45 * abs(dot(normal, frame.lightDirection.xyz));
  float foot = 0.75 + 0.25 * clamp(worldPosition.y / 1.2, 0.0, 1.0);
  vec3 c = vec3(0.78, 0.74, 0.68) * light * foot;
  color = vec4(pow(c, vec3(1.0 / 2.2)), 1.0);
}
