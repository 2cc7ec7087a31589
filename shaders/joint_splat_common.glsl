// What the splat passes share: a sprite (a splatted joint's ellipsoid and tint), its pixels'
// rays and the shading of one pixel of it into the visibility buffer. Needs joint_sprite.glsl, the
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

// The ray through pixel centre (px, py), unnormalized: w0 + py·wy + px·wx (pixelRay's direction
// before its normalize), and the clip-space z and w it adds per unit: k0 + py·ky + px·kx, the
// eye's being ke. Linear in the pixel, so a sprite's pixel takes its ray from its row's in a few
// multiplies instead of from the camera's (lavapipe moves nothing out of a loop: every
// per-sprite term would be computed again for every pixel). CPU twin: render::splatJointsCpu.
struct FrameRays {
  vec3 w0, wx, wy;
  vec2 k0, kx, ky, ke;
};

FrameRays frameRays() {
  FrameRays f;
  f.w0 = frame.rayForward.xyz - frame.rayRight.xyz - frame.rayDown.xyz;
  f.wx = frame.rayRight.xyz * (2.0 / frame.viewport.x);
  f.wy = frame.rayDown.xyz * (2.0 / frame.viewport.y);
  f.k0 = (frame.viewProjection * vec4(f.w0, 0.0)).zw;
  f.kx = (frame.viewProjection * vec4(f.wx, 0.0)).zw;
  f.ky = (frame.viewProjection * vec4(f.wy, 0.0)).zw;
  f.ke = (frame.viewProjection * vec4(frame.eye.xyz, 1.0)).zw;
  return f;
}

// The same rays in a sprite's unit-sphere space, where its ellipsoid is the unit sphere: the eye
// o and the pixel's ray d0 + py·dy + px·dx.
struct SpriteRays {
  mat3 inv;  // world → unit sphere, linear part
  vec3 o, d0, dx, dy;
};

SpriteRays spriteRays(vec4 inverse0, vec4 inverse1, vec4 inverse2, FrameRays f) {
  SpriteRays r;
  r.inv = transpose(mat3(inverse0.xyz, inverse1.xyz, inverse2.xyz));
  r.o = r.inv * frame.eye.xyz + vec3(inverse0.w, inverse1.w, inverse2.w);
  r.d0 = r.inv * f.w0;
  r.dx = r.inv * f.wx;
  r.dy = r.inv * f.wy;
  return r;
}

// A row's rays at px = 0: the unit-sphere and world rays and the clip terms.
struct RowRays {
  vec3 d, w;
  vec2 k;
};

RowRays rowRays(SpriteRays r, FrameRays f, int y) {
  float py = float(y) + 0.5;
  return RowRays(r.d0 + py * r.dy, f.w0 + py * f.wy, f.k0 + py * f.ky);
}

// The nearest hit of pixel (x, y) of the row with the sprite's ellipsoid, kept by a 64-bit
// atomicMin of (depth bits << 32 | colour); nothing where the ray misses. The ray is
// eye + s·w, w unnormalized, so its hit s is hitJoint's distance over |w| and the hit's clip
// z and w are ke + s·k.
void splatRayPixel(SpriteRays r, FrameRays f, RowRays row, int x, int y, vec3 tint) {
  float px = float(x) + 0.5;
  vec3 d = row.d + px * r.dx;
  float a = dot(d, d), b = dot(r.o, d);
  float disc = unitSphereDiscriminant(r.o, d);
  float s = (-b - sqrt(max(disc, 0.0))) / a;
  if (!(disc >= 0.0 && s > 0.0)) return;
  vec2 clip = f.ke + s * (row.k + px * f.kx);
  float depth = clip.x / clip.y;
  if (depth < 0.0 || depth > 1.0) return;
  vec3 n = normalize(transpose(r.inv) * (r.o + s * d));
  vec3 dir = normalize(row.w + px * f.wx);
  uint colour = packUnorm4x8(vec4(shadeJoint(tint, n, dir, frame.lightDirection.xyz), 1.0));
  uint64_t packed = (uint64_t(floatBitsToUint(depth)) << 32) | uint64_t(colour);
  atomicMin(visibility[uint(y) * uint(frame.viewport.x) + uint(x)], packed);
}

#endif
