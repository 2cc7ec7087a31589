// Descriptor binding numbers and specialization-constant ids of the crowd steering passes
// (grid, avoidance, advance, path goals): named once here, used by the shaders in
// `layout(binding = ...)` / `layout(constant_id = ...)` and by engine/crowd in gpu::*Binding and
// the specialization arrays, so neither side restates a number. Included like crowd_types.h.
#ifndef THRONG_CROWD_BINDINGS_H
#define THRONG_CROWD_BINDINGS_H

#ifdef __cplusplus
#include <cstdint>
namespace throng::gpu_types {
using uint = uint32_t;
#endif

// avoidance_grid_count.comp: each agent's cell and rank, counted per cell.
const uint kGridCountBindingPlacement = 0u;  // texels (x, y, z, heading)
const uint kGridCountBindingCellRank = 1u;
const uint kGridCountBindingCounts = 2u;

// avoidance_scan.comp: the cells' start slots (prefix sums of the counts).
const uint kGridScanBindingCounts = 0u;  // texels
const uint kGridScanBindingStarts = 1u;

// avoidance_scatter.comp: agents in cell order.
const uint kGridScatterBindingPlacement = 0u;  // texels
const uint kGridScatterBindingSteer = 1u;      // texels
const uint kGridScatterBindingCellRank = 2u;   // texels
const uint kGridScatterBindingStarts = 3u;     // texels
const uint kGridScatterBindingSortedIndex = 4u;
const uint kGridScatterBindingSorted = 5u;

// avoidance_steer.comp: the velocity each agent chooses.
const uint kSteerBindingPlacement = 0u;
const uint kSteerBindingMotion = 1u;
const uint kSteerBindingGoals = 2u;  // texels
const uint kSteerBindingSteer = 3u;
const uint kSteerBindingStarts = 4u;       // texels
const uint kSteerBindingSortedIndex = 5u;  // texels
const uint kSteerBindingSorted = 6u;       // texels
const uint kSteerBindingPlacementTexels = 7u;
const uint kSteerBindingSteerTexels = 8u;
const uint kSteerBindingWallInfo = 9u;       // uniform WallGridInfo
const uint kSteerBindingWallEntries = 10u;  // texels: per list entry its segment (a.x, a.z, b.x, b.z)
const uint kSteerBindingWallStarts = 11u;    // texels
// Its specialization constants (one 32-bit value each, in this order).
const uint kSteerConstantPolicy = 0u;  // kSteerPolicy*
const uint kSteerConstantRange = 1u;   // grid columns scanned each side
const uint kSteerConstantChunk = 2u;   // candidates per round
const uint kSteerConstantRangeZ = 3u;  // grid rows scanned each side
const uint kSteerConstantWalls = 4u;   // 1: static walls are read (the bindings above), 0: not
const uint kSteerConstantCount = 5u;

// avoidance_advance.comp: position += velocity · dt.
const uint kAdvanceBindingPlacement = 0u;
const uint kAdvanceBindingSteer = 1u;
const uint kAdvanceBindingGoals = 2u;

// wall_constraint.comp: no agent crosses a wall or ends within its radius of one.
const uint kWallBindingPlacement = 0u;
const uint kWallBindingPrevious = 1u;  // texels: each agent's placement before the step
const uint kWallBindingInfo = 2u;      // uniform WallGridInfo
const uint kWallBindingEntries = 3u;   // texels: per list entry its segment
const uint kWallBindingStarts = 4u;    // texels
const uint kWallBindingSteer = 6u;     // texels: the moving form's velocities (steer)
const uint kWallBindingGoals = 7u;     // texels: the moving form's goals (inactive: no move)
const uint kWallBindingClearance = 8u; // texels: per wall-grid cell, its distance to the walls
// Its specialization constant: 1, the agents move by steer · dt here (the kinematic advance and
// the constraint in one pass, from placement); 0, placement is constrained from `previous`.
const uint kWallConstantAdvance = 0u;

// path_goals.comp: the path-vector waypoints.
const uint kGoalsBindingAgentStart = 0u;
const uint kGoalsBindingAgentInfo = 1u;
const uint kGoalsBindingSourceRange = 2u;
const uint kGoalsBindingCumulative = 3u;
const uint kGoalsBindingGoals = 4u;

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
