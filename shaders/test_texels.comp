#version 450
#extension GL_GOOGLE_include_directive : require
// Test shader for uniform texel buffers: out[i] = dot(texel i, (1, 10, 100, 1000)).
#include "synth_bindings.h"
layout(local_size_x = 64) in;
layout(binding = kTestTexelsBindingTexels) uniform samplerBuffer texels;
layout(std430, binding = kTestTexelsBindingOutput) writeonly buffer Output { float outputs[]; };
layout(push_constant) uniform Push { uint count; } push;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  outputs[i] = dot(texelFetch(texels, int(i)), vec4(1.0, 10.0, 100.0, 1000.0));
}
