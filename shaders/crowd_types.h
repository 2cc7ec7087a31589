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
#define THRONG_CROWD_STRUCT(name) struct name
#else
#define THRONG_CROWD_STRUCT(name) struct name
#endif

// Per-agent buffers of the steering passes (structure of arrays beside placement/motion):
//   goal[i]   = (target x, target z, max speed, active: 1 or 0)  the path-vector waypoint
//   steer[i]  = (vx, vz, speed, flags or -steps waited)           the velocity chosen this step
//   sorted[k] = (x, z, vx, vz)                                    agent sortedIndex[k], cell order

const uint kSteerPolicyNone = 0u;   // follow the path vectors, ignore others
const uint kSteerPolicyRule = 1u;   // published rule: on overlap, a random heading in the gaze
const uint kSteerPolicyTtc = 2u;    // anticipatory power law (Karamouzas et al. 2014)

const uint kSteerFlagTurned = 1u;   // the rule turned the agent to a random heading this step
const uint kSteerFlagKept = 2u;     // the rule kept a free earlier heading instead of the blocked course
const uint kSteerFlagForced = 3u;   // no free heading for kRuleMaxWait s: the first draw anyway
const uint kSteerFlagWaiting = 4u;  // no free heading: the rule waits (steer.w = -steps waited)
const float kRuleMaxWait = 1.0;     // seconds
const uint kRuleDraws = 4u;         // random headings the rule draws per step (first free one taken)
const uint kScanBlock = 1024u;      // cells per workgroup of the block scan (256 threads × 4)

// Push constants of every grid pass (count, scan, scatter, cell sort).
THRONG_CROWD_STRUCT(GridPush) {
  uint agentCount;
  uint cellCount;        // power of two: cells are hashed, cell & (cellCount - 1)
  uint blockCount;       // ceil(cellCount / kScanBlock)
  uint pad0;
  float invCellSize;     // 1 / cell side in metres (multiplied, so GPU and CPU floor alike)
  float pad1;
  float pad2;
  float pad3;
};

// Push constants of the steering pass.
THRONG_CROWD_STRUCT(SteerPush) {
  uint agentCount;
  uint cellCount;
  uint policy;           // kSteerPolicy*
  uint step;             // step counter: the rule's draw k hashes (agent, step · kRuleDraws + k, seed)
  uint seed;
  int cellRange;         // neighbour cells scanned each side: ceil(sensing / cell)
  float invCellSize;
  float dt;
  float invSecondsLeft;  // 1 / time until the current waypoint is due
  float radius;          // safe radius of each cylinder (metres)
  float sensing;         // neighbours farther than this are ignored
  float lookahead;       // rule: seconds ahead the overlap is tested
  float gazeAngle;       // rule: full width of the random turn (radians)
  float ttcK;            // TTC: k (m²/s²·s^m), tau0 (s), relaxation xi (s), force cap (m/s²)
  float ttcTau0;
  float ttcXi;
  float ttcMaxForce;
  float slowSpeed;       // root speeds of the clip pair: speed → w (motion.z)
  float fastSpeed;
  float cosHalfGaze;     // rule: cos(gazeAngle / 2), the cone a kept heading must stay in
};

// Push constants of the kinematic advance (position += velocity · dt).
THRONG_CROWD_STRUCT(AdvancePush) {
  uint agentCount;
  float dt;
  float pad0;
  float pad1;
};

#ifdef __cplusplus
}  // namespace throng::gpu_types
#endif
#endif
