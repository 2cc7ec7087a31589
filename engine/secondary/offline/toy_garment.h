#pragma once
// A tiny deterministic stand-in for the cloth simulator, for tests and quick runs of the
// exploration: a pendulum chain hanging from the neck of a two-speed toy run graph (two cycles
// of 8 and 6 frames joined at their ends), with gravity, air drag, a chest sphere and
// inextensible links. Cheap (microseconds a step) but history-dependent like real cloth, so
// merges have errors and expansions reduce them.
#include <cstdint>
#include <memory>

#include "secondary/secondary_types.h"

namespace throng::secondary {

struct ToyGarmentOptions {
  uint32_t links = 6;        // chain vertices after the pinned one
  float linkLength = 0.08f;  // metres
  uint32_t substeps = 4;
  float drag = 10.0f;  // 1/s against still air (strong: a light chain is chaotic)
};

// Joints "Hips" (root) and "Neck"; nodes (clip 0, bucket b, frame f), b = 0 slow (8 frames),
// b = 1 fast (6 frames); next-frame edges and, at each cycle end, edges to frame 0 of both.
PrimaryGraph makeToyPrimaryGraph();
// The chain: vertex 0 pinned to the neck, the others hanging below it.
ClothMesh makeToyChain(const PrimaryGraph& graph, const ToyGarmentOptions& options);
// The chain at rest under the neck of `node`, moving with the character.
ClothState toyRestState(const ClothMesh& mesh, const PrimaryGraph& graph, uint32_t node);
StepFunction makeToyStepFunction(std::shared_ptr<const PrimaryGraph> graph,
                                 std::shared_ptr<const ClothMesh> mesh,
                                 const ToyGarmentOptions& options);

}  // namespace throng::secondary
