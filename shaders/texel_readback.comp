#version 450
#extension GL_GOOGLE_include_directive : require
// Reads a motion texture back through texelFetch, as the paper's shaders sample it, together
// with the parent array SSBO; used by the motion-texture round-trip test.
#include "synth_bindings.h"
layout(local_size_x = 64) in;
layout(binding = kTexelReadbackBindingTexture) uniform sampler2D motionTexture;
layout(std430, binding = kTexelReadbackBindingParents) readonly buffer Parents { int parents[]; };
layout(std430, binding = kTexelReadbackBindingTexels) writeonly buffer Texels { vec4 texels[]; };
layout(std430, binding = kTexelReadbackBindingParentsOut) writeonly buffer ParentsOut { int parentsOut[]; };
layout(push_constant) uniform Push { uint width; uint height; uint jointCount; } push;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < push.jointCount) parentsOut[i] = parents[i];
  if (i >= push.width * push.height) return;
  ivec2 texel = ivec2(i % push.width, i / push.width);
  texels[i] = texelFetch(motionTexture, texel, 0);
}
