// The body of cache_classify.comp, cache_classify_groups.comp (which defines
// THRONG_CACHE_CLASSIFY_GROUPS: every clip set of a crowd in one dispatch, each character's
// cache from its group's entry in the group table, the groups' bucketSlot in one buffer) and
// cache_classify_scheduled.comp (THRONG_CACHE_CLASSIFY_SCHEDULED: the update-rate LOD's moved
// chunks, a workgroup each, update_rate.h).
// Motion cache, step 4 (one invocation per character of a chunk, or of the crowd). A character whose bucket is
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
#if defined(THRONG_CACHE_CLASSIFY_GROUPS)
layout(push_constant) uniform Push { ClassifyGroupsPush push; };
layout(std140, binding = kCacheClassifyBindingGroups) uniform Groups { SynthGroupTable table; };
#elif defined(THRONG_CACHE_CLASSIFY_SCHEDULED)
layout(push_constant) uniform Push { ClassifySchedulePush push; };
layout(std430, binding = kCacheClassifyBindingChunkList) readonly buffer ChunkList { uvec2 chunkList[]; };
layout(std430, binding = kCacheClassifyBindingArgs) readonly buffer Args { ScheduledClassifyArgs args; };
#else
layout(push_constant) uniform Push { CachePush push; };
#endif

// Where a character's cache is: its bucket's slot at bucketSlot[slotBase + bucket], its entries
// rowCount rows from dataBase; its pose chunk (listed from the chunk's first character).
struct CacheOf {
  uint slotBase, bucketCount, rowCount, dataBase, chunk, chunkFirst;
};

#ifndef THRONG_CACHE_CLASSIFY_SCHEDULED
CacheOf cacheOf(uint i) {
#ifdef THRONG_CACHE_CLASSIFY_GROUPS
  // Chunks of push.chunkSize characters, numbered across groups, each group's from its first
  // character.
  uint group = 0u;
  [[unroll]] for (uint k = 1u; k < kSynthMaxGroups; ++k)
    if (k < table.counts.x && i >= table.groups[k].firstCharacter) group = k;
  SynthGroupInfo g = table.groups[group];
  // (i - first) / chunkSize by a float division (lavapipe divides integer vectors lane by
  // lane); the half keeps the quotient away from whole numbers for any approximate division
  // (root_motion.glsl says why), exact below 2^23 characters.
  uint inGroup = uint(floor((float(i - g.firstCharacter) + 0.5) / float(push.chunkSize)));
  return CacheOf(g.bucketBase, push.bucketCount, g.cacheRowCount, g.cacheDataBase, push.firstChunk[group] + inGroup,
                 g.firstCharacter + inGroup * push.chunkSize);
#else
  return CacheOf(0u, uint(bucketSlot.length()), push.rowCount, push.dataBase, push.chunk, push.firstCharacter);
#endif
}
#endif

// Character i: its pose source, and when its bucket is not resident its place in its pose
// chunk's list.
void classify(uint i, CacheOf cache) {
  vec4 m = texelFetch(motionTexels, int(i));
  int slot = bucketSlot[cache.slotBase + speedBucket(speedWeight(m), push.bucketWidth, cache.bucketCount)];
  if (slot >= 0) {
    // The nearest row; phase · R rounding up to R is row 0 again. Mirrors synth::cacheRow.
    uint row = uint(cyclePhase(m) * float(cache.rowCount) + 0.5);
    if (row >= cache.rowCount) row = 0u;
    poseSource[i] = cache.dataBase + (uint(slot) * cache.rowCount + row) * push.jointCount;
    return;
  }
  poseSource[i] = kPoseInJoints;
  uint index = atomicAdd(listCounts[cache.chunk], 1u);
  characterList[cache.chunkFirst + index] = i - cache.chunkFirst;
}

#ifdef THRONG_CACHE_CLASSIFY_SCHEDULED
// A workgroup per listed chunk (or per chunk), an invocation per character.
void main() {
  uint chunk = args.allChunks != 0u ? gl_WorkGroupID.x : chunkList[gl_WorkGroupID.x].x;
  uint i = chunk * kUpdateChunkCharacters + gl_LocalInvocationID.x;
  if (i >= push.characterCount) return;
  uint poseChunk = i / push.poseChunk;
  classify(i, CacheOf(0u, uint(bucketSlot.length()), push.rowCount, push.dataBase, poseChunk,
                      poseChunk * push.poseChunk));
}
#else
void main() {
  uint local = gl_GlobalInvocationID.x;
  if (local >= push.characterCount) return;
  classify(push.firstCharacter + local, cacheOf(push.firstCharacter + local));
}
#endif
