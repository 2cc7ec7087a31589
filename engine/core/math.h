#pragma once
// Math shared by the CPU twins. Formulas here are mirrored line by line in shaders/common.glsl
// so that GPU and CPU results agree to float rounding.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace throng {

constexpr float kPi = 3.14159265358979323846f;

// Shortest-arc spherical interpolation of unit quaternions (x,y,z,w in a vec4), the formula
// used by every synthesis path. Falls back to normalized lerp when the quaternions are nearly
// parallel, where sin(theta) would lose precision.
inline glm::vec4 slerpShortest(glm::vec4 a, glm::vec4 b, float t) {
  float cosTheta = glm::dot(a, b);
  if (cosTheta < 0.0f) {
    b = -b;
    cosTheta = -cosTheta;
  }
  if (cosTheta > 0.9995f) return glm::normalize(a + t * (b - a));
  float theta = std::acos(cosTheta);
  float sinTheta = std::sin(theta);
  float wa = std::sin((1.0f - t) * theta) / sinTheta;
  float wb = std::sin(t * theta) / sinTheta;
  return wa * a + wb * b;
}

// Slerp without acos/sin (D. Eberly, "A Fast and Accurate Algorithm for Computing SLERP"):
// sin(tθ)/sin(θ) expanded as a series in (cos θ − 1), the last term scaled by (1 + μ). Only
// multiplies and adds, so lavapipe vectorizes it and the GPU matches the CPU twin to float
// rounding. The arc is halved first: slerp(a, b, t) is slerp(a, m, 2t) below t = ½ and
// slerp(m, b, 2t − 1) above, m the normalized midpoint. After the shortest-arc flip cos θ ≥ 0,
// so the half arc has cos(θ/2) ≥ 0.707, where 4 terms reach a coefficient error of 6.5e-7 (the
// whole range needs 12 for 7.2e-7); the tests measure the quaternion error against slerpShortest.
constexpr int kSlerpTerms = 4;
constexpr float kSlerpOnePlusMu = 1.142f;

// The parts of the series that depend only on t: which half of the arc, the parameter within
// it, and (u_i t² − v_i) for the weights of both ends. A character blends all its joints with
// one t, so these are computed once per character.
struct SlerpWeights {
  bool upperHalf = false;       // t ≥ ½: from the midpoint to b
  float t = 0.0f;               // the parameter within the half: 2t or 2t − 1
  float termsT[kSlerpTerms];    // for sin(tθ)/sin θ
  float termsD[kSlerpTerms];    // for sin((1−t)θ)/sin θ
};

inline SlerpWeights makeSlerpWeights(float tWhole) {
  SlerpWeights s;
  s.upperHalf = tWhole >= 0.5f;
  const float t = s.upperHalf ? 2.0f * tWhole - 1.0f : 2.0f * tWhole;
  s.t = t;
  float d = 1.0f - t;
  for (int i = 1; i <= kSlerpTerms; ++i) {
    float u = 1.0f / float(i * (2 * i + 1));
    float v = float(i) / float(2 * i + 1);
    if (i == kSlerpTerms) {
      u *= kSlerpOnePlusMu;
      v *= kSlerpOnePlusMu;
    }
    s.termsT[i - 1] = u * t * t - v;
    s.termsD[i - 1] = u * d * d - v;
  }
  return s;
}

inline glm::vec4 slerpFast(glm::vec4 a, glm::vec4 b, const SlerpWeights& s) {
  float cosTheta = glm::dot(a, b);
  float sign = cosTheta < 0.0f ? -1.0f : 1.0f;
  float cosWhole = sign * cosTheta;
  glm::vec4 end = sign * b;
  float inverseLength = 1.0f / std::sqrt(2.0f + 2.0f * cosWhole);  // |a + end| = √(2 + 2 cos θ)
  glm::vec4 mid = (a + end) * inverseLength;
  float xm1 = (1.0f + cosWhole) * inverseLength - 1.0f;  // cos(θ/2) − 1
  float rT = 1.0f, rD = 1.0f;
  for (int i = kSlerpTerms - 1; i >= 0; --i) {
    rT = 1.0f + s.termsT[i] * xm1 * rT;
    rD = 1.0f + s.termsD[i] * xm1 * rD;
  }
  glm::vec4 from = s.upperHalf ? mid : a;
  glm::vec4 to = s.upperHalf ? end : mid;
  return ((1.0f - s.t) * rD) * from + (s.t * rT) * to;
}

inline glm::vec4 slerpFast(glm::vec4 a, glm::vec4 b, float t) { return slerpFast(a, b, makeSlerpWeights(t)); }

inline glm::quat toQuat(glm::vec4 q) { return glm::quat(q.w, q.x, q.y, q.z); }
inline glm::vec4 toVec4(glm::quat q) { return glm::vec4(q.x, q.y, q.z, q.w); }

// Hamilton product of (x,y,z,w) quaternions.
inline glm::vec4 quatMul(glm::vec4 a, glm::vec4 b) {
  return glm::vec4(a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
                   a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
                   a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
                   a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z);
}

inline glm::vec3 quatRotate(glm::vec4 q, glm::vec3 v) {
  glm::vec3 u(q.x, q.y, q.z);
  glm::vec3 t = 2.0f * glm::cross(u, v);
  return v + q.w * t + glm::cross(u, t);
}

// Rotation about +y by `angle` radians; heading 0 faces +z.
inline glm::vec4 yawQuat(float angle) {
  return glm::vec4(0.0f, std::sin(0.5f * angle), 0.0f, std::cos(0.5f * angle));
}

}  // namespace throng
