#version 450
#extension GL_GOOGLE_include_directive : require
// Test shader for the dispatch path: out[i] = in[i] * scale + i.
#include "synth_bindings.h"
layout(local_size_x = 64) in;
layout(std430, binding = kTestScaleBindingInput) readonly buffer Input { float inputs[]; };
layout(std430, binding = kTestScaleBindingOutput) writeonly buffer Output { float outputs[]; };
layout(push_constant) uniform Push { float scale; uint count; } push;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  outputs[i] = inputs[i] * push.scale + float(i);
}
