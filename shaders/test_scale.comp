#version 450
// Test shader for the dispatch path: out[i] = in[i] * scale + i.
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Input { float inputs[]; };
layout(std430, binding = 1) writeonly buffer Output { float outputs[]; };
layout(push_constant) uniform Push { float scale; uint count; } push;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  outputs[i] = inputs[i] * push.scale + float(i);
}
