#include "secondary/cloth_playback.h"

#include <algorithm>

#include "core/error.h"
#include "shaders/shared_types.h"
#include "synth/motion_cache.h"

namespace throng::secondary {

PlaybackTables makePlaybackTables(const ClothDatabase& db) {
  const PlaybackPrimary& p = db.primary;
  PlaybackTables t;
  t.bucketCount = uint32_t(p.run.framesPerBucket.size());
  t.runFirst.push_back(0);
  for (uint32_t frames : p.run.framesPerBucket) t.runFirst.push_back(t.runFirst.back() + frames);
  t.runNodes.assign(t.runFirst.back(), kNoNode);
  for (uint32_t n = 0; n < p.nodeCount(); ++n) {
    const PrimaryNode& node = p.nodes[n];
    if (node.clip != 0 || node.bucket >= t.bucketCount) continue;
    if (node.frame >= p.run.framesPerBucket[node.bucket]) continue;
    uint32_t& slot = t.runNodes[t.runFirst[node.bucket] + node.frame];
    if (slot == kNoNode) slot = n;
  }
  t.firstStateAtNode.assign(p.nodeCount(), kNoClothState);
  for (uint32_t s = db.stateCount(); s-- > 0;) t.firstStateAtNode[db.graph.stateNode[s]] = s;
  // The natural successor: same clip and bucket, the next frame (frame 0 after the cycle's last).
  t.naturalSuccessor.assign(p.nodeCount(), kNoNode);
  for (uint32_t n = 0; n < p.nodeCount(); ++n) {
    const PrimaryNode& a = p.nodes[n];
    for (uint32_t e = p.firstSuccessor[n]; e < p.firstSuccessor[n + 1]; ++e) {
      const PrimaryNode& b = p.nodes[p.successors[e]];
      if (b.clip != a.clip || b.bucket != a.bucket) continue;
      if (b.frame == a.frame + 1) {
        t.naturalSuccessor[n] = e - p.firstSuccessor[n];
        break;
      }
      if (b.frame == 0 && t.naturalSuccessor[n] == kNoNode)
        t.naturalSuccessor[n] = e - p.firstSuccessor[n];
    }
  }
  return t;
}

uint32_t characterNode(const ClothDatabase& db, const PlaybackTables& t, glm::vec4 motion) {
  const RunGraphParams& run = db.primary.run;
  const uint32_t bucket =
      synth::speedBucket(gpu_types::speedWeight(motion), run.bucketWidth, t.bucketCount);
  const uint32_t frames = run.framesPerBucket[bucket];
  if (frames == 0) return kNoNode;
  // Same arithmetic as shaders/cloth_common.glsl (float product, truncation, clamp).
  float phase = std::max(gpu_types::cyclePhase(motion), 0.0f);
  uint32_t frame = std::min(uint32_t(phase * float(frames)), frames - 1u);
  return t.runNodes[t.runFirst[bucket] + frame];
}

namespace {
uint32_t successorIndex(const PlaybackPrimary& p, uint32_t from, uint32_t to) {
  for (uint32_t e = p.firstSuccessor[from]; e < p.firstSuccessor[from + 1]; ++e)
    if (p.successors[e] == to) return e - p.firstSuccessor[from];
  return kNoNode;
}

// The cape switches trajectories: it blends from `shown` unless a blend is already under way, in
// which case that blend goes on (a new one from the bare state would drop the source's share of
// what is on screen: a jump of up to that share of several frames' motion).
void startBlend(ClothCharacter& c, uint32_t shown) {
  if (c.countdown > 0) {
    --c.countdown;
    return;
  }
  c.blendSource = shown;
  c.countdown = kMergeBlendFrames;
}
}  // namespace

bool advanceCharacter(const ClothDatabase& db, const PlaybackTables& t, ClothCharacter& c,
                      glm::vec4 motion) {
  const uint32_t target = characterNode(db, t, motion);
  if (target == kNoNode || target == c.node) return false;
  const PlaybackPrimary& p = db.primary;
  const PlaybackGraph& g = db.graph;
  if (c.node != kNoNode && c.state != kNoClothState) {
    // Walk: the direct edge if there is one, else natural successors to catch up skipped frames.
    ClothCharacter walk = c;
    bool merged = false;
    for (uint32_t step = 0; step < kMaxWalkSteps; ++step) {
      uint32_t k = successorIndex(p, walk.node, target);
      const bool arrived = k != kNoNode;
      if (!arrived) k = t.naturalSuccessor[walk.node];
      if (k == kNoNode) break;
      const uint32_t edge = g.firstEdge[walk.state] + k;
      if (g.edgeIsMerge[edge]) {
        merged = true;
        startBlend(walk, walk.state);
      } else if (walk.countdown > 0) {
        --walk.countdown;
      }
      walk.state = g.edgeTarget[edge];
      walk.node = p.successors[p.firstSuccessor[walk.node] + k];
      if (arrived) {
        c = walk;
        return merged;
      }
    }
  }
  // Not reachable along the graph (first frame, or a jump): the first state at the new node,
  // blended from the old one when there was one.
  const uint32_t state = t.firstStateAtNode[target];
  if (state == kNoClothState) return false;
  const bool jumped = c.state != kNoClothState;
  if (jumped) startBlend(c, c.state);
  c.state = state;
  c.node = target;
  return jumped;
}

}  // namespace throng::secondary
