// Structs of the crowd steering passes (grid + avoidance), shared by C++ and GLSL like
// shared_types.h. C++ includes this file through crowd/avoidance_types.h (static_asserts).
#ifndef THRONG_CROWD_TYPES_H
#define THRONG_CROWD_TYPES_H

#ifdef __cplusplus
#include <cstdint>
#include <glm/glm.hpp>
namespace throng::gpu_types {
using vec4 = glm::vec4;
using uint = uint32_t;
using uvec4 = glm::uvec4;
#define THRONG_CROWD_STRUCT(name) struct name
#else
#define THRONG_CROWD_STRUCT(name) struct name
#endif

// Per-agent buffers of the steering passes (structure of arrays beside placement/motion):
//   goal[i]     = (target x, target z, max speed, active: 1 or 0)  the path-vector waypoint
//   steer[i]    = (vx, vz, speed, flags or -steps waited)           the velocity chosen this step
//   cellRank[i] = (grid cell, rank of the agent among its cell's)  written by the count pass
//   sorted[k]   = (x, z, vx, vz)                                    agent sortedIndex[k], cell order
//
// The grid: cells of 1 / invCellX by 1 / invCellZ metres, laid out row-major in a table of
// 2^widthShift columns × (rowMask + 1) rows with the coordinates taken modulo the table (no
// hash), so the cells x-1, x, x+1 of one row are adjacent in the sorted order: a neighbour
// scan reads one or two runs of slots per row. Cells that alias (a table apart) are far away,
// and the distance test drops their agents.

const uint kSteerPolicyNone = 0u;   // follow the path vectors, ignore others
const uint kSteerPolicyRule = 1u;   // published rule: on overlap, a random heading in the gaze
const uint kSteerPolicyTtc = 2u;    // anticipatory power law (Karamouzas et al. 2014)

const uint kSteerFlagTurned = 1u;   // the rule turned the agent to a random heading this step
const uint kSteerFlagKept = 2u;     // the rule kept a free earlier heading instead of the blocked course
const uint kSteerFlagForced = 3u;   // no free heading for kRuleMaxWait s: the first draw anyway
const uint kSteerFlagWaiting = 4u;  // no free heading: the rule waits (steer.w = -steps waited)
const float kRuleMaxWait = 1.0;     // seconds
const uint kRuleDraws = 4u;         // random headings the rule draws per step (first free one taken)
const uint kScanThreads = 256u;     // the scan pass: one workgroup, each thread a run of cells
const uint kMaxClipSets = 4u;       // speed → w mappings (clip pairs) per steering pass
const uint kPathHoldsEnd = 0x80000000u;  // path source range bit: stay at the last waypoint, no loop

// TTC forces are summed in fixed point (1/kForceScale m/s², each neighbour's term clamped to
// ±kForceTermCap per axis), so the sum does not depend on the order neighbours are visited in:
// the grid's order within a cell is the count pass's atomic order, and the CPU twin's differs.
// A term that large already exceeds the cap on the total (ttcMaxForce <= kForceTermCap / 2);
// 32-bit sums hold 511 such terms.
const float kForceScale = 65536.0;
const float kForceTermCap = 64.0;

// Density-dependent walking speed (docs/design.md, "Density slows walkers"): each agent's local
// density ahead is a kernel sum over the neighbours within R in the half disc it heads into,
// w = (1 − d²/R²)², normalised by 6 / (π R²) (the kernel's integral over the half disc) and
// summed in fixed point (1/kDensityScale per unit of weight) so the order neighbours come in
// does not matter. Only the space ahead counts: people adapt to the headway in front of them,
// and the front of a queue, with nobody ahead, walks off. Its speed is capped at the preferred
// speed times Weidmann's (1993) fundamental diagram v(ρ)/v0 = 1 − exp(−γ (1/ρ − 1/ρmax)),
// floored at kDensityMinSpeed so a jam still creeps forward instead of locking for ever.
const float kDensityScale = 65536.0;
const float kWeidmannGamma = 1.913;      // m⁻²
const float kWeidmannMaxDensity = 5.4;   // persons/m², where the diagram reaches 0
const float kDensityMinSpeed = 0.1;      // fraction of the preferred speed

// Push constants of every grid pass (count, scan, scatter).
THRONG_CROWD_STRUCT(GridPush) {
  uint agentCount;
  uint cellCount;        // (rowMask + 1) << widthShift
  uint widthShift;       // log2 of the table's columns
  uint rowMask;          // rows − 1 (a power of two minus one)
  float invCellX;        // 1 / cell width (x) in metres (multiplied, so GPU and CPU floor alike)
  float invCellZ;        // 1 / cell depth (z): one row of the table
  float pad1;
  float pad2;
};

// Push constants of the steering pass (policy, neighbour range and subgroup chunk are
// specialization constants).
THRONG_CROWD_STRUCT(SteerPush) {
  uint agentCount;
  uint step;             // step counter: the rule's draw k hashes (agent, step · kRuleDraws + k, seed)
  uint seed;
  uint widthShift;       // the grid table (GridPush)
  uint rowMask;
  float invCellX;        // 1 / cell width and depth (GridPush)
  float dt;
  float invSecondsLeft;  // 1 / time until the current waypoint is due
  float radius;          // safe radius of each cylinder (metres)
  float sensing;         // neighbours farther than this are ignored
  float lookahead;       // rule: seconds ahead the overlap is tested
  float gazeAngle;       // rule: full width of the random turn (radians)
  float cosHalfGaze;     // rule: cos(gazeAngle / 2), the cone a kept heading must stay in
  float ttcK;            // TTC: k (m²/s²·s^m), relaxation xi (s), force cap (m/s²)
  float densityInvRadius2;  // density-dependent speed: 1 / R² of the kernel (0: off)
  float ttcXi;
  float ttcMaxForce;
  float ttcInvTau0;      // 1 / tau0
  float invCellZ;
  float densityNorm;     // persons/m² per unit of kernel weight: 6 / (π R²) (0: off)
  // Speed → w (motion.z) per clip pair: agents [setEnd[k−1], setEnd[k]) use the root speeds
  // setSlow[k], setFast[k] (w = 0 when fast <= slow is left alone: motion.z unchanged).
  uvec4 setEnd;
  vec4 setSlow;
  vec4 setFast;
};

// Push constants of the kinematic advance (position += velocity · dt).
THRONG_CROWD_STRUCT(AdvancePush) {
  uint agentCount;
  float dt;
  float pad0;
  float pad1;
};

// Static walls (crowd/obstacles.h): segments binned once into a grid of their own. Cell (c, r)
// covers origin + [c, c+1) × [r, r+1) / invCell and lists every segment within `reach` of it,
// so an agent reads one cell's list: segments[k] = (a.x, a.z, b.x, b.z) for the k in
// indices[starts[cell] .. starts[cell + 1]). A uniform block, read once per invocation.
THRONG_CROWD_STRUCT(WallGridInfo) {
  vec4 frame;  // (origin x, origin z, 1 / cell size, reach)
  uvec4 size;  // (columns, rows, segments, 0); columns = 0: no walls
};
const float kWallSkin = 1.0e-4;  // metres the constraint keeps beyond the radius (obstacles.h)
const uint kWallContacts = 3u;   // contacts a move slides along before it stops at the last

// Push constants of the wall constraint (agents [first, first + count)).
THRONG_CROWD_STRUCT(WallPush) {
  uint first;
  uint count;
  float radius;   // safe radius kept from every segment (plus kWallSkin)
  float maxMove;  // reach − radius: longer moves are shortened (the cell lists end at reach)
  float dt;       // the moving form: seconds of the step
  float pad0;
  float pad1;
  float pad2;
};

// Push constants of the goal pass (path-vector waypoints for one simulated second).
THRONG_CROWD_STRUCT(GoalPush) {
  uint agentCount;
  uint second;           // the simulation second whose waypoints are written
  uint pad0;
  uint pad1;
};

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
