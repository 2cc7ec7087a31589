// The update-rate LOD, shared by C++ and GLSL like shared_types.h (C++ includes it through
// synth/update_rate.h, which checks the sizes): a chunk of
// kUpdateChunkCharacters consecutive characters whose largest projected height is h pixels
// moves every k-th step, k the largest whole number up to maxInterval with
// (k − 1) · lagPerHeight · h ≤ maxLag (not only powers of two: a chunk that may wait 7 steps
// moves a seventh of the time, not a quarter):
// between two of its updates a character is drawn where it was at the first, and no point of
// its joints moves more than lagPerHeight · h pixels in a step (lagPerHeight = dt · the pair's
// fastest joint point speed / standing height, update_rate.h in engine/synth). Blocks of
// 2^blockShift chunks are staggered (a chunk of block b is due at steps where step + b is a
// multiple of k), so each step moves about the same share of the crowd, in runs of consecutive
// chunks: memory read in long runs (on the 2-core VM a quarter of the chunks moved cost 0.27 of
// moving all of them with blocks of 256, 0.36 staggered chunk by chunk). Each update moves by
// the seconds of every step since the chunk's last. A character that cannot reach the view before
// its chunk's next move (RootMotionPush::reachPerHeight) counts as 0 px tall: a chunk of such
// characters moves every maxInterval steps, and none of them walks into view lagging.
#ifndef THRONG_UPDATE_RATE_H
#define THRONG_UPDATE_RATE_H

#include "shared_types.h"

#ifdef __cplusplus
namespace throng::gpu_types {
#define THRONG_UPDATE_INLINE inline
#else
#define THRONG_UPDATE_INLINE
#endif

const uint kUpdateChunkCharacters = 64u;  // root motion's workgroup
const uint kUpdateMaxInterval = 8u;

// Push constants of update_schedule.comp.
THRONG_STRUCT(UpdateSchedulePush) {
  uint chunkCount;
  uint step;            // this step's number (wraps; only differences are used)
  float lagPerHeight;   // pixels a joint point moves per step per pixel of projected height
  float maxLag;         // pixels
  uint maxInterval;     // 1 to kUpdateMaxInterval
  uint blockShift;      // chunks are staggered in blocks of 2^blockShift (updateBlockShift)
  uint pad1;
  uint pad2;
  // sinceSeconds[j]: the seconds of the last j + 1 steps, this one's included. Steps vary in
  // length (the viewer's follow the wall clock, a pause's are 0), so a chunk moved after e steps
  // advances by their sum.
  float sinceSeconds[kUpdateMaxInterval];
};

// Push constants of cache_classify_scheduled.comp: the motion cache's classify over the chunks
// that moved (a character that stood still keeps its pose source and, when not cached, the
// joints the pose pass wrote for it), or over every chunk when the cache filled an entry this
// step (it may have evicted one that a still character's pose source names).
THRONG_STRUCT(ClassifySchedulePush) {
  uint characterCount;  // the crowd's (one clip set, from character 0)
  uint rowCount;        // poses per cache entry
  float bucketWidth;
  uint dataBase;        // the cache's first point in the data buffer
  uint jointCount;
  uint poseChunk;       // characters per pose chunk: a miss is listed in its chunk's list
  uint pad0;
  uint pad1;
};
// cache_classify_args.comp's output: the classify's VkDispatchIndirectCommand (a workgroup per
// listed chunk, or per chunk) and whether it covers every chunk.
THRONG_STRUCT(ScheduledClassifyArgs) {
  uint x;
  uint y;
  uint z;
  uint allChunks;
};
// The steps between a chunk's updates when its largest character is maxHeight pixels tall.
THRONG_UPDATE_INLINE uint updateInterval(float maxHeight, float lagPerHeight, float maxLag,
                                  uint maxInterval) {
  uint k = 1u;
  while (k < maxInterval && float(k) * lagPerHeight * maxHeight <= maxLag) ++k;
  return k;
}

// Whether chunk `chunk`, last moved at step `last`, moves at `step`: at its block's staggered
// slot, or once its interval has passed (after the interval grew).
THRONG_UPDATE_INLINE bool updateDue(uint step, uint last, uint chunk, uint interval,
                                    uint blockShift) {
  return step - last >= interval || ((step + (chunk >> blockShift)) % interval) == 0u;
}

#undef THRONG_UPDATE_INLINE

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
