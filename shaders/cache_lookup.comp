#version 450
#extension GL_GOOGLE_include_directive : require
// Motion cache, step 1 (one invocation per character of a group): flag the speed bucket it needs this frame.
#include "shared_types.h"
#include "synth_bindings.h"
#include "speed_buckets.glsl"

layout(local_size_x = 64) in;
layout(constant_id = kCacheLookupConstantCharactersPerInvocation) const uint kPerInvocation = 1u;
layout(binding = kCacheLookupBindingMotion) uniform samplerBuffer motionTexels;  // texels: see root_motion.comp
layout(std430, binding = kCacheLookupBindingCounters) buffer Counters { CacheCounters counters; };
layout(std430, binding = kCacheLookupBindingRequested) writeonly buffer Requested { uint requested[]; };
layout(push_constant) uniform Push { CachePush push; };

// kPerInvocation characters each, strided (see root_motion.comp).
void main() {
  uint stride = (push.characterCount + kPerInvocation - 1u) / kPerInvocation;
  if (gl_GlobalInvocationID.x >= stride) return;
  for (uint k = 0u; k < kPerInvocation; ++k) {
    uint local = gl_GlobalInvocationID.x + k * stride;
    if (local >= push.characterCount) break;
    vec4 m = texelFetch(motionTexels, int(push.firstCharacter + local));
    requested[speedBucket(speedWeight(m), push.bucketWidth, counters.bucketCount)] = 1u;
  }
}
