#version 450
#extension GL_GOOGLE_include_directive : require
// Motion cache, step 5: turn the list counts into indirect dispatch sizes (64 per group).
#include "synth_bindings.h"
layout(local_size_x = 64) in;
layout(std430, binding = kCacheArgsBindingListCounts) readonly buffer ListCounts { uint listCounts[]; };
layout(std430, binding = kCacheArgsBindingDispatchArgs) writeonly buffer DispatchArgs { uint dispatchArgs[]; };
layout(push_constant) uniform Push { uint countCount; } push;

void main() {
  uint k = gl_GlobalInvocationID.x;
  if (k >= push.countCount) return;
  dispatchArgs[3u * k] = (listCounts[k] + 63u) / 64u;
  dispatchArgs[3u * k + 1u] = 1u;
  dispatchArgs[3u * k + 2u] = 1u;
}
