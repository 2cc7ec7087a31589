// The motion texels the pose pass and the cache fill read (texel (x, f) is element f·2J + x),
// from storage buffers as two 64-bit words each (words64.glsl), or, when the host put
// them in uniform buffers (kTexelsInUniform: a CPU device and both clips within
// kUniformTexels), from there: lavapipe gathers uniform data with unrolled loads, no loop.
#ifndef THRONG_MOTION_TEXELS_GLSL
#define THRONG_MOTION_TEXELS_GLSL

#include "synth_bindings.h"
#include "words64.glsl"

layout(constant_id = kTexelsConstantUniformTexels) const int kUniformTexels = 1;
layout(constant_id = kTexelsConstantInUniform) const bool kTexelsInUniform = false;
layout(std430, binding = kTexelsBindingSlow) readonly buffer SlowMotion { u64vec2 slowMotion[]; };
layout(std430, binding = kTexelsBindingFast) readonly buffer FastMotion { u64vec2 fastMotion[]; };
layout(std140, binding = kTexelsBindingSlowUniform) uniform SlowUniform { vec4 slowUniform[kUniformTexels]; };
layout(std140, binding = kTexelsBindingFastUniform) uniform FastUniform { vec4 fastUniform[kUniformTexels]; };

vec4 slowTexel(int i) {
  if (kTexelsInUniform) return slowUniform[i];
  return fromWords(slowMotion[i]);
}

vec4 fastTexel(int i) {
  if (kTexelsInUniform) return fastUniform[i];
  return fromWords(fastMotion[i]);
}

#endif
