#version 450
#extension GL_GOOGLE_include_directive : require
// Cloth playback, draw: flat two-sided lighting from the screen-space derivatives of the world
// position (no normals are decoded), the normal turned towards the eye.
#include "cloth_types.h"
#include "cloth_bindings.h"

layout(std140, binding = kClothDrawBindingView) uniform View { ClothView view; };
layout(location = 0) in vec3 worldPosition;
layout(location = 1) flat in vec3 tint;
layout(location = 0) out vec4 colour;

void main() {
  vec3 n = normalize(cross(dFdx(worldPosition), dFdy(worldPosition)));
  if (dot(n, view.eye.xyz - worldPosition) < 0.0) n = -n;
  float diffuse = max(dot(n, view.light.xyz), 0.0);
  colour = vec4(tint * (0.35 + 0.65 * diffuse), 1.0);
}
