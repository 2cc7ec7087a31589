// What the splat passes share: a sprite (a splatted joint's ellipsoid and tint)
// and the shading of one pixel of it into the visibility buffer. Needs joint_sprite.glsl, the
// Frame uniform and the Visibility buffer first. CPU twin: render::splatJointsCpu.
#ifndef THRONG_JOINT_SPLAT_COMMON_GLSL
#define THRONG_JOINT_SPLAT_COMMON_GLSL

#include "joint_splat_counters.glsl"

struct SplatSprite {
  vec4 inverse0;  // JointSprite's world → unit-sphere rows
  vec4 inverse1;
  vec4 inverse2;
  vec4 tint;      // xyz
};

// The nearest hit of pixel (x, y) with the sprite's ellipsoid, kept by a 64-bit atomicMin of
// (depth bits << 32 | colour); nothing where the ray misses.
void splatPixel(int x, int y, vec4 inverse0, vec4 inverse1, vec4 inverse2, vec3 tint) {
  vec3 dir = pixelRay(vec2(x, y) + 0.5, frame);
  float t;
  vec3 n;
  if (!hitJoint(frame.eye.xyz, dir, inverse0, inverse1, inverse2, t, n)) return;
  vec4 clip = frame.viewProjection * vec4(frame.eye.xyz + t * dir, 1.0);
  float depth = clip.z / clip.w;
  if (depth < 0.0 || depth > 1.0) return;
  uint colour = packUnorm4x8(vec4(shadeJoint(tint, n, dir, frame.lightDirection.xyz), 1.0));
  uint64_t packed = (uint64_t(floatBitsToUint(depth)) << 32) | uint64_t(colour);
  atomicMin(visibility[uint(y) * uint(frame.viewport.x) + uint(x)], packed);
}

#endif
