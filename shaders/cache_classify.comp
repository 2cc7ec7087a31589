#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
// Motion cache, step 4 (one invocation per character of a chunk). A character whose bucket is
// resident gets its poseSource: the row of its cache entry nearest its phase (rows are dense
// enough for smooth playback, synth::cacheRowCount says why), from which the renderer composes
// A = M · P, so synthesis writes nothing per joint for it. The
// others are listed for the full pose pass (dispatched indirectly over just them, since
// lavapipe would execute both sides of a divergent branch).
#include "shared_types.h"
#include "synth_bindings.h"
#include "motion_common.glsl"
#include "speed_buckets.glsl"

layout(local_size_x = 64) in;
layout(binding = kCacheClassifyBindingMotion) uniform samplerBuffer motionTexels;  // texels: see root_motion.comp
layout(std430, binding = kCacheClassifyBindingBucketSlot) readonly buffer BucketSlot { int bucketSlot[]; };
layout(std430, binding = kCacheClassifyBindingCharacterList) writeonly buffer CharacterList { uint characterList[]; };
layout(std430, binding = kCacheClassifyBindingListCounts) buffer ListCounts { uint listCounts[]; };
layout(std430, binding = kCacheClassifyBindingPoseSource) writeonly buffer PoseSource { uint poseSource[]; };
layout(push_constant) uniform Push { CachePush push; };

void main() {
  uint local = gl_GlobalInvocationID.x;
  if (local >= push.characterCount) return;
  uint i = push.firstCharacter + local;
  vec4 m = texelFetch(motionTexels, int(i));
  int slot = bucketSlot[speedBucket(speedWeight(m), push.bucketWidth, uint(bucketSlot.length()))];
  if (slot >= 0) {
    // The nearest row; phase · R rounding up to R is row 0 again. Mirrors synth::cacheRow.
    uint row = uint(cyclePhase(m) * float(push.rowCount) + 0.5);
    if (row >= push.rowCount) row = 0u;
    poseSource[i] = push.dataBase + (uint(slot) * push.rowCount + row) * push.jointCount;
    return;
  }
  poseSource[i] = kPoseInJoints;
  uint index = atomicAdd(listCounts[push.chunk], 1u);
  characterList[push.firstCharacter + index] = local;
}
