#pragma once
// Playback of a compressed cloth database on a crowd, on the CPU: the twin of the GPU passes
// (cloth_gpu_jobs.h). Each character's cloth follows its own traversal of the secondary graph:
// every frame its primary node is (clip 0, bucket of its speed weight, floor(phase · F_b)); when
// the node moves along successor k of the previous node, the cloth state moves along edge k of
// its state. Frames skipped between two calls are walked along the natural (next-frame)
// successors; any other jump goes to the first state at the new node. Crossing a merge edge (or
// jumping) blends from the state left behind to the new trajectory over kMergeBlendFrames; one
// that comes while a blend is under way lets that blend go on, so the blend always starts from
// what the cape shows (shownClothPositions) and never jumps.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "secondary/cloth_database.h"
#include "shaders/cloth_types.h"

namespace throng::secondary {

using gpu_types::ClothCharacter;
constexpr uint32_t kNoClothState = 0xFFFFFFFFu;
// Natural successors followed at most to catch up with a character that skipped frames.
constexpr uint32_t kMaxWalkSteps = 4;

// Lookup tables of a database, shared by the CPU twin and the GPU buffers.
struct PlaybackTables {
  uint32_t bucketCount = 0;
  std::vector<uint32_t> runFirst;  // per bucket: start of its frames in runNodes (bucketCount + 1)
  std::vector<uint32_t> runNodes;  // node of (bucket, frame), or kNoNode
  std::vector<uint32_t> firstStateAtNode;  // per node: the lowest state there, or kNoClothState
  std::vector<uint32_t>
      naturalSuccessor;  // per node: k of the next frame of its clip and bucket, or kNoNode
};
PlaybackTables makePlaybackTables(const ClothDatabase& db);

inline ClothCharacter noClothCharacter() {
  return {kNoClothState, kNoNode, kNoClothState, 0u};
}

// The character's primary node for motion = (phase, w, wTarget, scale); kNoNode when the graph has
// no node for its bucket.
uint32_t characterNode(const ClothDatabase& db, const PlaybackTables& t, glm::vec4 motion);

// One frame of a character's traversal (see the file comment). Returns true when the frame
// crossed a merge edge or jumped (the cape switched trajectories: a blend starts or goes on).
bool advanceCharacter(const ClothDatabase& db, const PlaybackTables& t, ClothCharacter& c,
                      glm::vec4 motion);

// Weight of the blend source in the shown cloth: countdown / (kMergeBlendFrames + 1).
inline float blendSourceWeight(const ClothCharacter& c) {
  return c.countdown > 0 ? float(c.countdown) / float(kMergeBlendFrames + 1) : 0.0f;
}

}  // namespace throng::secondary
