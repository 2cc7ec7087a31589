// Math shared by the synthesis shaders; mirrors engine/core/math.h and the CPU twin in
// engine/anim/reference_synth.cpp operation for operation.
#ifndef THRONG_MOTION_COMMON_GLSL
#define THRONG_MOTION_COMMON_GLSL

// Series slerp, mirrors slerpFast in engine/core/math.h (see there for the error bound). The
// t-dependent terms are computed once per character (makeSlerpWeights) and reused by all joints.
const int kSlerpTerms = 4;
const float kSlerpOnePlusMu = 1.142;

struct SlerpWeights {
  bool upperHalf;
  float t;
  float termsT[kSlerpTerms];
  float termsD[kSlerpTerms];
};

SlerpWeights makeSlerpWeights(float tWhole) {
  SlerpWeights s;
  s.upperHalf = tWhole >= 0.5;
  float t = s.upperHalf ? 2.0 * tWhole - 1.0 : 2.0 * tWhole;
  s.t = t;
  float d = 1.0 - t;
  [[unroll]] for (int i = 1; i <= kSlerpTerms; ++i) {
    float u = 1.0 / float(i * (2 * i + 1));
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

vec4 slerpFast(vec4 a, vec4 b, SlerpWeights s) {
  float cosTheta = dot(a, b);
  float sign = cosTheta < 0.0 ? -1.0 : 1.0;
  float cosWhole = sign * cosTheta;
  vec4 end = sign * b;
  float inverseLength = inversesqrt(2.0 + 2.0 * cosWhole);
  vec4 mid = (a + end) * inverseLength;
  float xm1 = (1.0 + cosWhole) * inverseLength - 1.0;
  float rT = 1.0, rD = 1.0;
  [[unroll]] for (int i = kSlerpTerms - 1; i >= 0; --i) {
    rT = 1.0 + s.termsT[i] * xm1 * rT;
    rD = 1.0 + s.termsD[i] * xm1 * rD;
  }
  vec4 from = s.upperHalf ? mid : a;
  vec4 to = s.upperHalf ? end : mid;
  return ((1.0 - s.t) * rD) * from + (s.t * rT) * to;
}

vec4 quatMul(vec4 a, vec4 b) {
  return vec4(a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
              a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
              a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
              a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z);
}

vec3 quatRotate(vec4 q, vec3 v) {
  vec3 t = 2.0 * cross(q.xyz, v);
  return v + q.w * t + cross(q.xyz, t);
}

vec4 yawQuat(float angle) { return vec4(0.0, sin(0.5 * angle), 0.0, cos(0.5 * angle)); }

// A speed weight in [lo, hi] drawn for a character at a speed-change epoch (PCG hash); mirrors
// anim::retargetSpeed.
float retargetSpeed(uint character, uint epoch, uint seed, float lo, float hi) {
  uint h = character * 747796405u + epoch * 2891336453u + seed * 1181783497u + 12345u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  h = (h >> 22u) ^ h;
  return lo + (hi - lo) * float(h >> 8) * (1.0 / 16777216.0);
}

// Where a clip is sampled at a phase in [0, 1): between rows `row` and `next` at fraction t (the
// row after the last is row 0: clips are cycles). Mirrors anim::clipSample, snap included.
const float kRowSnap = 1e-4;
struct ClipSample {
  int row;
  int next;
  float t;
};

ClipSample clipSample(float phase, uint frames) {
  float x = phase * float(frames);
  float nearest = floor(x + 0.5);
  if (abs(x - nearest) < kRowSnap) x = nearest;  // a phase meant to land on a row lands on it
  if (x >= float(frames)) x -= float(frames);    // a phase just below 1 is row 0 of the next cycle
  ClipSample s;
  s.row = int(min(uint(x), frames - 1u));
  s.next = s.row + 1 == int(frames) ? 0 : s.row + 1;
  s.t = min(x - float(s.row), 1.0);
  return s;
}

#endif
