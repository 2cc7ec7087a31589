#version 450
#extension GL_GOOGLE_include_directive : require
// Motion cache, step 1 (one invocation per character of a group): flag the speed bucket it needs this frame.
#include "shared_types.h"
#include "synth_bindings.h"
#include "speed_buckets.glsl"

layout(local_size_x = 64) in;
layout(binding = kCacheLookupBindingMotion) uniform samplerBuffer motionTexels;  // texels: see root_motion.comp
layout(std430, binding = kCacheLookupBindingCounters) buffer Counters { CacheCounters counters; };
layout(std430, binding = kCacheLookupBindingRequested) writeonly buffer Requested { uint requested[]; };
layout(push_constant) uniform Push { CachePush push; };

void main() {
  if (gl_GlobalInvocationID.x >= push.characterCount) return;
  vec4 m = texelFetch(motionTexels, int(push.firstCharacter + gl_GlobalInvocationID.x));
  requested[speedBucket(speedWeight(m), push.bucketWidth, counters.bucketCount)] = 1u;
}
