#pragma once
// Types shared by the parts of the secondary-motion module (docs/design.md "Secondary motion
// graphs", Kim et al. 2013): the primary motion graph the crowd plays, cloth states, the
// cape mesh, and the black-box simulator interface the exploration calls.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace throng::secondary {

// One pose the crowd can show. For the run pair: clip 0, bucket = motion-cache speed bucket,
// frame f of the cycle at that bucket's speed (phase = f / framesInCycle). Other clips
// (walk, idle, jump) have their own clip index and bucket 0.
struct PrimaryNode {
  uint32_t clip = 0;
  uint32_t bucket = 0;
  uint32_t frame = 0;
};

// Character-space joint transform at a node (root at the origin facing +z, heading 0).
struct NodeJoint {
  glm::vec3 position{0.0f};
  glm::vec4 rotation{0.0f, 0.0f, 0.0f, 1.0f};  // quaternion x, y, z, w
};

// Nodes are poses, edges are next-frame and transitions. `successors[n]` lists the nodes a
// character at n may show next frame; after pruning every node has at least one successor
// and the graph is strongly connected.
struct PrimaryGraph {
  float frameTime = 1.0f / 30.0f;
  uint32_t jointCount = 0;
  std::vector<int32_t> parents;         // per joint, −1 for the root
  std::vector<std::string> jointNames;  // per joint (BVH names: finds neck, shoulders)
  std::vector<PrimaryNode> nodes;
  std::vector<std::vector<uint32_t>> successors;
  std::vector<NodeJoint> poses;  // nodes × jointCount
  // Root displacement in character space from a node to each successor (same shape as
  // successors): the simulator moves the cloth's world frame by it.
  std::vector<std::vector<glm::vec3>> rootStep;

  const NodeJoint* pose(uint32_t node) const { return poses.data() + size_t(node) * jointCount; }
};

// A cloth state: vertex positions and velocities in character space at one primary node.
struct ClothState {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> velocities;
};

// The garment's mesh: rest positions (character space, T-pose), triangles, and the vertices
// pinned to joints (pinned vertex i follows joint pinJoint[i] rigidly).
struct ClothMesh {
  std::vector<glm::vec3> restPositions;
  std::vector<uint32_t> triangles;  // 3 indices per triangle
  std::vector<uint32_t> pinnedVertices;
  std::vector<uint32_t> pinJoints;
  // Per pinned vertex: its position in joint pinJoints[i]'s frame (added by the cloth part).
  // Empty: the rest positions are taken to be at primary node 0's pose.
  std::vector<glm::vec3> pinOffsets;
  uint32_t vertexCount() const { return uint32_t(restPositions.size()); }
};

// The black box of the paper: simulate one primary edge (one frame) from a cloth state.
// Must be deterministic and thread-safe (expansions run in parallel).
using StepFunction =
    std::function<ClothState(const ClothState& from, uint32_t fromNode, uint32_t toNode)>;

// What playback needs of an explored secondary graph. State s sits at primary node
// stateNode[s]; when the character moves along successors[stateNode[s]][k] the cloth goes to
// edgeTarget[firstEdge[s] + k], and edgeIsMerge says that edge is a merge (blended over
// kMergeBlendFrames at playback). firstEdge has states + 1 entries.
struct PlaybackGraph {
  std::vector<uint32_t> stateNode;
  std::vector<uint32_t> firstEdge;
  std::vector<uint32_t> edgeTarget;
  std::vector<uint8_t> edgeIsMerge;
  uint32_t stateCount() const { return uint32_t(stateNode.size()); }
};
constexpr uint32_t kMergeBlendFrames = 10;

}  // namespace throng::secondary
