#version 450
#extension GL_GOOGLE_include_directive : require
// Ray-casts the joint's ellipsoid (a unit sphere after the inverse affine map) through this
// pixel, writes its true depth, and lights it: directional + sky ambient + a little rim so
// silhouettes read at a distance.
#include "shared_types.h"

layout(std140, binding = 1) uniform Frame { FrameUniforms frame; };
layout(location = 0) flat in vec3 tint;
layout(location = 1) flat in vec4 inverse0;
layout(location = 2) flat in vec4 inverse1;
layout(location = 3) flat in vec4 inverse2;
layout(location = 0) out vec4 color;

void main() {
  vec2 ndc = gl_FragCoord.xy / frame.viewport.xy * 2.0 - 1.0;
  vec3 eye = frame.eye.xyz;
  vec3 dir = normalize(frame.rayForward.xyz + ndc.x * frame.rayRight.xyz + ndc.y * frame.rayDown.xyz);
  mat3 inv = transpose(mat3(inverse0.xyz, inverse1.xyz, inverse2.xyz));
  vec3 o = inv * eye + vec3(inverse0.w, inverse1.w, inverse2.w);
  vec3 d = inv * dir;
  float a = dot(d, d), b = dot(o, d), c = dot(o, o) - 1.0;
  float disc = b * b - a * c;
  if (disc < 0.0) discard;
  float t = (-b - sqrt(disc)) / a;
  if (t <= 0.0) discard;
  vec3 hit = eye + t * dir;
  vec4 clip = frame.viewProjection * vec4(hit, 1.0);
  gl_FragDepth = clip.z / clip.w;
  vec3 n = normalize(transpose(inv) * (o + t * d));
  float diffuse = max(dot(n, frame.lightDirection.xyz), 0.0);
  float sky = 0.5 + 0.5 * n.y;
  float rim = pow(1.0 - max(dot(n, -dir), 0.0), 3.0);
  vec3 col = tint * (0.28 + 0.22 * sky + 0.75 * diffuse) + 0.12 * rim;
  color = vec4(pow(col, vec3(1.0 / 2.2)), 1.0);
}
