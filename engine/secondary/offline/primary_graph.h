#pragma once
// The primary motion graph (Kim et al. 2013, §3): the poses a character can show and the
// frame-to-frame moves between them. For the crowd the nodes are the motion cache's
// (speed bucket, frame) poses of the run cycle and the transitions are the cycle ends where the
// synthesizer may change speed, so the cloth follows exactly the motion the crowd plays.
// Other clips join through pose + velocity transitions; pruning keeps the strongly connected
// part so no traversal ever reaches a dead end.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "anim/clip.h"
#include "anim/default_clips.h"
#include "anim/motion_texture.h"
#include "core/binary_io.h"
#include "secondary/secondary_types.h"

namespace throng::secondary {

// The synthesizer's cycle duration at speed weight w (stepCharacter's rule: the slow and fast
// durations blended by w) and the whole number of frames the graph gives that cycle,
// max(2, round(duration / frameTime)).
float runCycleDuration(const anim::MotionPair& pair, float w);
uint32_t runCycleFrames(const anim::MotionPair& pair, float w, float frameTime);

// Nodes (clip 0, bucket b, frame f) for every speed bucket b of the motion cache
// (synth::speedBucketCount(bucketWidth)) and f < runCycleFrames(w_b); pose = the
// character-space pose at phase f / F_b and w_b. Edges: (b, f) → (b, f + 1), and at a cycle
// end (b, F_b − 1) → (b', 0) for every b' in increasing order. rootStep = the mean per-frame
// travel of the blended cycle, cycleTravel(w_b) / F_b (horizontal; the height is in the pose).
// The graph's frame time is the slow clip's. Joint names come from `skeleton`, which must have
// the pair's joint count.
PrimaryGraph buildRunGraph(const anim::MotionPair& pair, const anim::Skeleton& skeleton,
                           float bucketWidth);
PrimaryGraph buildRunGraph(const anim::ClipPair& clips, float bucketWidth);

// The successor a character keeps to when nothing changes: the next frame of the same clip and
// bucket (frame 0 after a cycle end), else successors[n][0].
uint32_t naturalSuccessor(const PrimaryGraph& graph, uint32_t node);
// Index of `to` in successors[from]; throws Error when it is not an edge.
uint32_t edgeIndex(const PrimaryGraph& graph, uint32_t from, uint32_t to);

// One more clip in character space (root above the origin, x/z travel taken out into the
// steps), ready to join a graph.
struct ClipPoses {
  std::string name;
  uint32_t jointCount = 0;
  bool cyclic = false;
  std::vector<int32_t> parents;      // must equal the graph's to join it
  std::vector<NodeJoint> poses;      // frames × jointCount
  std::vector<glm::vec3> rootSteps;  // step f → f + 1; a cycle also has last → 0
  uint32_t frameCount() const { return jointCount ? uint32_t(poses.size() / jointCount) : 0u; }
};
// Forward kinematics of every frame; the steps are the root's horizontal displacement (for a
// cycle, last → first adds cycleTravel).
ClipPoses clipPoses(const anim::Clip& clip, bool cyclic);

struct TransitionOptions {
  // Pose + velocity distance below which two poses are joined: RMS joint position difference
  // (m) + velocityWeight × RMS joint velocity difference (m/s, world velocities at heading 0).
  float threshold = 0.12f;
  float velocityWeight = 0.1f;  // seconds
  // At most this many transitions per clip frame and direction (the smallest distances).
  uint32_t maxPerFrame = 4;
};
struct TransitionReport {
  uint32_t clip = 0;          // the clip index the new nodes got
  uint32_t firstNode = 0;     // the new nodes are [firstNode, firstNode + frames)
  uint32_t intoClip = 0;      // edges added from graph nodes into the clip
  uint32_t outOfClip = 0;     // edges added from the clip into graph nodes
  float bestDistance = 0.0f;  // smallest pose + velocity distance met
};
// Pose + velocity distance between graph node a and frame c of the clip (TransitionOptions).
float transitionDistance(const PrimaryGraph& graph, uint32_t node, const ClipPoses& clip,
                         uint32_t frame, const TransitionOptions& options);
// Appends the clip's frames as nodes (new clip index, bucket 0) with their next-frame edges and
// joins them to the graph's existing nodes: where node a ≈ frame c (distance below the
// threshold and a local minimum along both), a → succ(c) and c → every successor of a. Not
// pruned: call pruneToStronglyConnected after the last clip.
TransitionReport addClipWithTransitions(PrimaryGraph& graph, const ClipPoses& clip,
                                        const TransitionOptions& options);

// Tarjan's strongly connected components; keeps the largest (ties: the one holding the lowest
// node index), in the old node order, with edges leaving it removed. Returns old → new index
// (−1 for removed nodes). Throws Error when no component has an edge.
std::vector<int32_t> pruneToStronglyConnected(PrimaryGraph& graph);

// True when every node has a successor and reaches every other node.
bool isStronglyConnected(const PrimaryGraph& graph);
// Throws Error naming the first inconsistency (array sizes, edge targets, rootStep shape).
void validatePrimaryGraph(const PrimaryGraph& graph);

// A versioned binary file with a checksum (binary_io.h chunks, magic "THRPRIMG"); load throws
// Error naming the file on a bad magic, version, size or checksum. save writes atomically.
// The chunk functions let another file (an explored graph) embed the primary graph; their tags
// all start with 'P'.
void addPrimaryGraphChunks(ChunkWriter& writer, const PrimaryGraph& graph);
PrimaryGraph readPrimaryGraphChunks(const ChunkReader& reader);
std::vector<uint8_t> encodePrimaryGraph(const PrimaryGraph& graph);
PrimaryGraph decodePrimaryGraph(std::span<const uint8_t> bytes, const std::string& sourceName);
void savePrimaryGraph(const std::filesystem::path& path, const PrimaryGraph& graph);
PrimaryGraph loadPrimaryGraph(const std::filesystem::path& path);

}  // namespace throng::secondary
