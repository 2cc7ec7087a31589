#version 450
#extension GL_GOOGLE_include_directive : require
// One point sprite per joint (one non-instanced point-list draw): the sprite covers the
// joint's ellipsoid on screen and the fragment shader ray-casts the ellipsoid exactly.
// One vertex and no triangle per joint, because lavapipe runs vertex processing and triangle
// setup on one CPU thread and pays for every vertex and primitive; points are the cheapest.
//
// The joint draw matrix A maps the unit mesh space (sphere of radius 1 around (0, 0.5, 0),
// squashed to y ∈ [0, 1]) to the world; B·u + c maps the unit sphere u to the world.
#include "shared_types.h"

layout(std430, binding = 0) readonly buffer Joints { JointMatrix joints[]; };
layout(std140, binding = 1) uniform Frame { FrameUniforms frame; };
layout(push_constant) uniform Push { DrawPush push; };

layout(location = 0) flat out vec3 tint;
layout(location = 1) flat out vec4 inverse0;  // rows of the world → unit-sphere affine map
layout(location = 2) flat out vec4 inverse1;
layout(location = 3) flat out vec4 inverse2;

vec3 hueToRgb(float h) {
  vec3 k = abs(fract(vec3(h) + vec3(0.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0);
  return clamp(k - 1.0, 0.0, 1.0);
}

uint hashIndex(uint x) {
  x ^= x >> 16; x *= 0x7feb352du; x ^= x >> 15; x *= 0x846ca68bu; x ^= x >> 16;
  return x;
}

void main() {
  uint joint = uint(gl_VertexIndex);
  uint character = joint / push.jointCount + push.firstCharacter;
  JointMatrix a = joints[joint];
  vec3 t = vec3(a.row0.w, a.row1.w, a.row2.w);
  vec3 b0 = vec3(a.row0.x, a.row1.x, a.row2.x);
  vec3 b1 = 0.5 * vec3(a.row0.y, a.row1.y, a.row2.y);
  vec3 b2 = vec3(a.row0.z, a.row1.z, a.row2.z);
  vec3 centre = t + b1;
  vec3 axisLengthSq = vec3(dot(b0, b0), dot(b1, b1), dot(b2, b2));
  vec4 clip = frame.viewProjection * vec4(centre, 1.0);
  float radius = sqrt(max(axisLengthSq.x, max(axisLengthSq.y, axisLengthSq.z)));
  if (min(axisLengthSq.x, min(axisLengthSq.y, axisLengthSq.z)) < 1e-10 || clip.w <= radius) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // zero-size or crossing the camera: not drawn
    gl_PointSize = 1.0;
    return;
  }
  // B = R·S, so B⁻¹ = S⁻² Bᵀ: rows are the columns over their squared lengths.
  vec3 r0 = b0 / axisLengthSq.x, r1 = b1 / axisLengthSq.y, r2 = b2 / axisLengthSq.z;
  inverse0 = vec4(r0, -dot(r0, centre));
  inverse1 = vec4(r1, -dot(r1, centre));
  inverse2 = vec4(r2, -dot(r2, centre));
  // Diameter of the bounding sphere's tangent-cone footprint, widened towards the screen edge
  // where the projection stretches, plus a pixel of margin.
  float distance = length(frame.eye.xyz - centre);
  float footprint = radius * distance / sqrt(distance * distance - radius * radius);
  float stretch = 1.0 + 0.5 * length(clip.xy / clip.w);
  gl_PointSize = min(2.0 * footprint * frame.viewport.z / clip.w * stretch + 2.0, 255.0);
  uint h = hashIndex(character);
  tint = mix(hueToRgb(float(h & 1023u) / 1024.0), vec3(0.85), 0.25) * (0.75 + 0.25 * float((h >> 10) & 3u) / 3.0);
  gl_Position = clip;
}
