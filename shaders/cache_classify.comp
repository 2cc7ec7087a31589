#version 450
#extension GL_GOOGLE_include_directive : require
// Motion cache, step 4 (one invocation per character of a chunk): list the character for the
// cached pose pass when its bucket is resident, else for the full pose pass, so that neither
// pass runs the other's code (lavapipe would execute both sides of a divergent branch).
#include "shared_types.h"
#include "cache_common.glsl"

layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Motion { vec4 motion[]; };
layout(std430, binding = 3) readonly buffer BucketSlot { int bucketSlot[]; };
layout(std430, binding = 6) writeonly buffer CharacterList { uint characterList[]; };
layout(std430, binding = 7) buffer ListCounts { uint listCounts[]; };
layout(push_constant) uniform Push { CachePush push; };

void main() {
  uint local = gl_GlobalInvocationID.x;
  if (local >= push.characterCount) return;
  float w = motion[push.firstCharacter + local].y;
  bool cached = bucketSlot[speedBucket(w, push.bucketWidth, uint(bucketSlot.length()))] >= 0;
  uint counter = 2u * push.chunk + (cached ? 0u : 1u);
  uint index = atomicAdd(listCounts[counter], 1u);
  characterList[push.firstCharacter + (cached ? 0u : push.listStride) + index] = local;
}
