#include "render/joint_splat_cpu.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "render/joint_splat.h"

namespace throng::render {
namespace {

float dotD(glm::vec4 a, glm::vec4 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z - a.w * b.w;
}

}  // namespace

// Mirrors jointSprite() in shaders/joint_sprite.glsl.
JointSpriteCpu jointSpriteCpu(const synth::JointMatrix& a, const gpu_types::FrameUniforms& frame) {
  JointSpriteCpu s;
  glm::vec3 t(a.row0.w, a.row1.w, a.row2.w);
  glm::vec3 b0(a.row0.x, a.row1.x, a.row2.x);
  glm::vec3 b1 = 0.5f * glm::vec3(a.row0.y, a.row1.y, a.row2.y);
  glm::vec3 b2(a.row0.z, a.row1.z, a.row2.z);
  glm::vec3 centre = t + b1;
  glm::vec3 lenSq(glm::dot(b0, b0), glm::dot(b1, b1), glm::dot(b2, b2));
  glm::vec4 clip = frame.viewProjection * glm::vec4(centre, 1.0f);
  float radius = std::sqrt(std::max(lenSq.x, std::max(lenSq.y, lenSq.z)));
  s.visible = std::min(lenSq.x, std::min(lenSq.y, lenSq.z)) >= 1e-10f && clip.w > radius;
  if (!s.visible) return s;
  glm::vec3 r0 = b0 / lenSq.x, r1 = b1 / lenSq.y, r2 = b2 / lenSq.z;
  s.inverse[0] = glm::vec4(r0, -glm::dot(r0, centre));
  s.inverse[1] = glm::vec4(r1, -glm::dot(r1, centre));
  s.inverse[2] = glm::vec4(r2, -glm::dot(r2, centre));
  glm::mat4 t4 = frame.viewProjection * glm::mat4(glm::vec4(b0, 0), glm::vec4(b1, 0),
                                                  glm::vec4(b2, 0), glm::vec4(centre, 1));
  glm::vec4 rx(t4[0].x, t4[1].x, t4[2].x, t4[3].x), ry(t4[0].y, t4[1].y, t4[2].y, t4[3].y);
  glm::vec4 rw(t4[0].w, t4[1].w, t4[2].w, t4[3].w);
  float qa = dotD(rw, rw), bx = dotD(rx, rw), cx = dotD(rx, rx), by = dotD(ry, rw),
        cy = dotD(ry, ry);
  if (qa >= 0.0f) {
    s.visible = false;
    return s;
  }
  float hx = std::sqrt(std::max(bx * bx - qa * cx, 0.0f)),
        hy = std::sqrt(std::max(by * by - qa * cy, 0.0f));
  glm::vec2 ndcLo(std::min((bx + hx) / qa, (bx - hx) / qa),
                  std::min((by + hy) / qa, (by - hy) / qa));
  glm::vec2 ndcHi(std::max((bx + hx) / qa, (bx - hx) / qa),
                  std::max((by + hy) / qa, (by - hy) / qa));
  glm::vec2 viewport(frame.viewport.x, frame.viewport.y);
  s.lo = (ndcLo * 0.5f + 0.5f) * viewport;
  s.hi = (ndcHi * 0.5f + 0.5f) * viewport;
  s.sizePx = std::max(s.hi.x - s.lo.x, s.hi.y - s.lo.y) + 2.0f;
  return s;
}

namespace {

uint32_t hashIndex(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

}  // namespace

glm::vec3 characterTintCpu(uint32_t character) {
  uint32_t h = hashIndex(character);
  float hue = float(h & 1023u) / 1024.0f;
  glm::vec3 k = glm::abs(
      glm::fract(glm::vec3(hue) + glm::vec3(0.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f);
  glm::vec3 rgb = glm::clamp(k - 1.0f, 0.0f, 1.0f);
  return glm::mix(rgb, glm::vec3(0.85f), 0.25f) * (0.75f + 0.25f * float((h >> 10) & 3u) / 3.0f);
}

namespace {

uint32_t packColour(glm::vec4 c) {
  uint32_t out = 0;
  for (int i = 0; i < 4; ++i)
    out |= uint32_t(std::lround(std::clamp(c[i], 0.0f, 1.0f) * 255.0f)) << (8 * i);
  return out;
}

}  // namespace

float unitSphereDiscriminantCpu(glm::vec3 o, glm::vec3 d) {
  const glm::vec3 across = glm::cross(o, d);
  return glm::dot(d, d) - glm::dot(across, across);
}

uint32_t shadeJointCpu(glm::vec3 tint, glm::vec3 n, glm::vec3 dir, glm::vec3 light) {
  float diffuse = std::max(glm::dot(n, light), 0.0f);
  float sky = 0.5f + 0.5f * n.y;
  float edge = 1.0f - std::max(glm::dot(n, -dir), 0.0f);
  float rim = edge * edge * edge;
  glm::vec3 col = tint * (0.28f + 0.22f * sky + 0.75f * diffuse) + 0.12f * rim;
  return packColour(glm::vec4(gpu_types::gammaEncode(col.x), gpu_types::gammaEncode(col.y),
                              gpu_types::gammaEncode(col.z), 1.0f));
}

namespace {

// frameRays() and spriteRays() of shaders/joint_splat_common.glsl: the ray through pixel centre
// (px, py) is w0 + py·wy + px·wx in the world, d0 + py·dy + px·dx in the sprite's unit-sphere
// space, and adds k0 + py·ky + px·kx per unit to the eye's clip z and w (ke).
struct FrameRaysCpu {
  glm::vec3 w0, wx, wy;
  glm::vec2 k0, kx, ky, ke;
};

glm::vec2 clipZw(const glm::mat4& viewProjection, glm::vec4 v) {
  const glm::vec4 clip = viewProjection * v;
  return {clip.z, clip.w};
}

FrameRaysCpu frameRaysCpu(const gpu_types::FrameUniforms& frame) {
  FrameRaysCpu f;
  const glm::vec3 right(frame.rayRight), down(frame.rayDown);
  f.w0 = glm::vec3(frame.rayForward) - right - down;
  f.wx = right * (2.0f / frame.viewport.x);
  f.wy = down * (2.0f / frame.viewport.y);
  f.k0 = clipZw(frame.viewProjection, glm::vec4(f.w0, 0.0f));
  f.kx = clipZw(frame.viewProjection, glm::vec4(f.wx, 0.0f));
  f.ky = clipZw(frame.viewProjection, glm::vec4(f.wy, 0.0f));
  f.ke = clipZw(frame.viewProjection, glm::vec4(glm::vec3(frame.eye), 1.0f));
  return f;
}

struct SpriteRaysCpu {
  glm::mat3 inv;
  glm::vec3 o, d0, dx, dy;
};

SpriteRaysCpu spriteRaysCpu(const JointSpriteCpu& s, const FrameRaysCpu& f, glm::vec3 eye) {
  SpriteRaysCpu r;
  r.inv = glm::transpose(
      glm::mat3(glm::vec3(s.inverse[0]), glm::vec3(s.inverse[1]), glm::vec3(s.inverse[2])));
  r.o = r.inv * eye + glm::vec3(s.inverse[0].w, s.inverse[1].w, s.inverse[2].w);
  r.d0 = r.inv * f.w0;
  r.dx = r.inv * f.wx;
  r.dy = r.inv * f.wy;
  return r;
}

// splatRayPixel() of joint_splat_common.glsl: pixel (x, y)'s packed nearest hit with the
// sprite's ellipsoid, or kEmptyPixel where its ray misses.
uint64_t splatRayPixelCpu(const SpriteRaysCpu& r, const FrameRaysCpu& f, int x, int y,
                          glm::vec3 tint, glm::vec3 light) {
  const float px = float(x) + 0.5f, py = float(y) + 0.5f;
  const glm::vec3 d = (r.d0 + py * r.dy) + px * r.dx;
  const float a = glm::dot(d, d), b = glm::dot(r.o, d);
  const float disc = unitSphereDiscriminantCpu(r.o, d);
  const float s = (-b - std::sqrt(std::max(disc, 0.0f))) / a;
  if (!(disc >= 0.0f && s > 0.0f)) return kEmptyPixel;
  const glm::vec2 clip = f.ke + s * ((f.k0 + py * f.ky) + px * f.kx);
  const float depth = clip.x / clip.y;
  if (depth < 0.0f || depth > 1.0f) return kEmptyPixel;
  const glm::vec3 n = glm::normalize(glm::transpose(r.inv) * (r.o + s * d));
  const glm::vec3 dir = glm::normalize((f.w0 + py * f.wy) + px * f.wx);
  uint32_t depthBits;
  std::memcpy(&depthBits, &depth, sizeof(depthBits));
  return (uint64_t(depthBits) << 32) | shadeJointCpu(tint, n, dir, light);
}

}  // namespace

SplatCpuResult splatJointsCpu(std::span<const synth::JointMatrix> joints,
                              const gpu_types::FrameUniforms& frame, uint32_t jointCount,
                              float maxPixels, uint32_t width, uint32_t height) {
  SplatCpuResult result;
  result.visibility.assign(size_t(width) * height, kEmptyPixel);
  const glm::vec3 eye(frame.eye);
  const glm::vec3 light(frame.lightDirection);
  const FrameRaysCpu rays = frameRaysCpu(frame);
  for (uint32_t joint = 0; joint < joints.size(); ++joint) {
    JointSpriteCpu s = jointSpriteCpu(joints[joint], frame);
    if (!s.visible) continue;
    if (s.sizePx > maxPixels) {
      result.nearJoints.push_back(joint);
      continue;
    }
    glm::ivec2 lo = glm::max(glm::ivec2(glm::ceil(s.lo - 0.5f)), glm::ivec2(0));
    glm::ivec2 hi =
        glm::min(glm::ivec2(glm::floor(s.hi - 0.5f)), glm::ivec2(int(width) - 1, int(height) - 1));
    const glm::vec3 tint = characterTintCpu(joint / jointCount);
    const SpriteRaysCpu sprite = spriteRaysCpu(s, rays, eye);
    for (int y = lo.y; y <= hi.y; ++y) {
      for (int x = lo.x; x <= hi.x; ++x) {
        uint64_t& pixel = result.visibility[size_t(y) * width + x];
        pixel = std::min(pixel, splatRayPixelCpu(sprite, rays, x, y, tint, light));
      }
    }
  }
  return result;
}

}  // namespace throng::render
