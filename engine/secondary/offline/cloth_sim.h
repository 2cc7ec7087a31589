#pragma once
// The black-box cloth simulator of the secondary motion graph: XPBD (Macklin et al. 2016) with
// small substeps ("Small Steps in Physics Simulation", 2019). Stretch constraints on the mesh
// edges (grid edges and diagonals), bending constraints between the two vertices facing each
// other across every inner edge, long-range attachments to the pinned vertices, gravity, air
// drag, internal damping, capsules on the bones and the ground.
//
// State: positions in the character space of the state's primary node (root above the origin,
// facing +z); velocities relative to the ground (still air), in the same axes. One frame along
// primary edge a → b is simulated in a's character space, with pinned vertices and capsules
// moving from a's pose to b's pose shifted by the edge's root step; the result is shifted back
// by the root step into b's character space. So a running character's cape streams behind it
// (drag against the air) while the state stays small and comparable between traversals.
//
// Deterministic: a step is a pure function of its inputs (fixed order, no shared mutable
// state), so concurrent calls from any number of threads give bit-identical results.
// Exploration runs expansions in parallel; a single step is single-threaded.
#include <cstdint>
#include <memory>

#include "secondary/offline/body_capsules.h"
#include "secondary/secondary_types.h"

namespace throng::secondary {

struct ClothSimOptions {
  uint32_t substeps = 10;   // per frame
  uint32_t iterations = 1;  // constraint sweeps per substep
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};
  float drag = 1.0f;  // 1/s: velocity against still air decays as exp(−drag · t)
  // 1/s, the cloth's own friction (0: none): each substep h, every constraint takes
  // 1 − exp(−internalDamping · h) of its two vertices' relative velocity away. Flutter dies out,
  // so explored states stay close enough to compress well (on the cape: max error 35 → 6 mm).
  float internalDamping = 0.0f;
  float areaDensity = 0.25f;       // kg/m² (lumped to vertices by triangle area)
  float stretchCompliance = 0.0f;  // m/N, mesh edges
  float bendCompliance = 0.05f;    // m/N, vertex pairs across inner edges
  // Long-range attachments: a free vertex may get no further from its nearest pinned vertex
  // than attachmentSlack × their rest distance (stops the slow stretch of one iteration).
  bool longRangeAttachments = true;
  float attachmentSlack = 1.02f;
  float thickness = 0.01f;  // kept from capsules and ground
  bool ground = true;
  float groundHeight = 0.0f;
  std::vector<BoneCapsule> capsules = defaultBodyCapsules();
};

// Throws Error on options out of range.
void validateClothSimOptions(const ClothSimOptions& options);

// Precomputed, read-only simulation data (constraints, masses, per-node pin targets and
// capsules) shared by every step.
class ClothModel;
std::shared_ptr<const ClothModel> makeClothModel(std::shared_ptr<const PrimaryGraph> graph,
                                                 std::shared_ptr<const ClothMesh> mesh,
                                                 const ClothSimOptions& options);
// One frame along the primary edge from → to (throws Error when it is not an edge or the state
// does not fit the mesh).
ClothState stepCloth(const ClothModel& model, const ClothState& from, uint32_t fromNode,
                     uint32_t toNode);
// The step as the exploration's black box; holds the model.
StepFunction makeClothStepFunction(std::shared_ptr<const PrimaryGraph> graph,
                                   std::shared_ptr<const ClothMesh> mesh,
                                   const ClothSimOptions& options);

// Pinned vertices where their joints hold them at `node`, the other vertices moved with them
// by the mean displacement of the pins (a rigid shift of the rest shape); every velocity is the
// character's own (root step of the node's natural successor / frame time). Not settled: run
// settleCloth before using it as an initial state.
ClothState restState(const ClothMesh& mesh, const PrimaryGraph& graph, uint32_t node);

// Simulates at least `minFrames` frames from `state` at `node` along natural successors
// (naturalSuccessor) and stops when the walk is back at `node`, so the result is a settled
// state at `node`. Throws Error when that walk never returns to `node`.
ClothState settleCloth(const StepFunction& step, const PrimaryGraph& graph, ClothState state,
                       uint32_t node, uint32_t minFrames);

// Lumped vertex masses (kg) of the mesh at areaDensity, for energies and tests.
std::vector<float> vertexMasses(const ClothMesh& mesh, float areaDensity);

}  // namespace throng::secondary
