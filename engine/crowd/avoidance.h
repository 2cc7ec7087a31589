#pragma once
// Collision avoidance (DESIGN.md "Storyboards"): each agent is a cylinder of a safe radius;
// every step a uniform grid is built by counting sort (count per cell, exclusive prefix sum,
// scatter) and each agent looks at the agents of the nearby cells. Policies:
//   * None: head for the path-vector waypoint, ignore others (the baseline of the metrics);
//   * Rule (the published one): if the course towards the waypoint makes the safe cylinders
//     overlap within the next `lookahead` seconds (closest approach, others keeping their
//     velocity), turn to a random heading within the gaze angle around
//     that course — random from a hash of (agent, step, seed), so the CPU twin draws the same
//     numbers. Of kRuleDraws draws per step the first whose course is free is taken; with none
//     free the agent waits, for at most kRuleMaxWait seconds before taking the first draw
//     anyway (dense crossings would otherwise wait for ever). A turn is kept on later steps
//     while its own course stays free and within the gaze (a new draw every step would
//     average back to the blocked course). Agents already too close may always move apart;
//   * Ttc: Karamouzas, Skinner & Guy 2014 ("Universal power law governing pedestrian
//     interactions"): an anticipatory force from the time to collision, plus relaxation
//     towards the waypoint velocity.
// The output of a step is the heading (placement.w) and velocity/speed (steer) each agent
// takes, and its speed weight (motion.z, taken up by the root-motion pass at the cycle end).
// This file is the CPU twin; avoidance_jobs.h records the same passes on the GPU.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace throng::crowd {

enum class SteerPolicy : uint32_t { None = 0, Rule = 1, Ttc = 2 };
std::optional<SteerPolicy> parseSteerPolicy(std::string_view name);  // "none", "rule", "ttc"
std::string_view steerPolicyName(SteerPolicy policy);

struct AvoidanceParams {
  SteerPolicy policy = SteerPolicy::Ttc;
  float cellSize = 3.0f;     // grid cell side (m)
  float radius = 0.3f;       // safe radius of every cylinder (m)
  float sensing = 3.0f;      // neighbours farther than this are ignored (m)
  float lookahead = 1.0f;    // rule: seconds ahead the overlap is tested
  float gazeAngle = 1.5708f; // rule: full width of the random turn (rad), 90°
  float ttcK = 1.5f;         // TTC constants of the paper: k, τ0 (s), relaxation ξ (s)
  float ttcTau0 = 3.0f;
  float ttcXi = 0.54f;
  float ttcMaxForce = 20.0f; // cap of the avoidance acceleration (m/s²)
  uint32_t seed = 1;
};
// Problems with the parameters (empty when valid).
std::vector<std::string> validateParams(const AvoidanceParams& params);
// Neighbour cells scanned on each side: ceil(sensing / cellSize).
int cellRange(const AvoidanceParams& params);

// What changes from step to step.
struct SteerFrame {
  float dt = 0.0f;           // seconds of this step
  float secondsLeft = 1.0f;  // until the current waypoint is due (> 0)
  uint32_t step = 0;         // hashed into the rule's random turn
  float slowSpeed = 0.0f;    // root speeds of the clip pair: speed → motion.z = w
  float fastSpeed = 0.0f;
};

// Hashed grid table size: the power of two ≥ agents, within [1024, 2^20] (the scan handles
// up to 1024 blocks of kScanBlock cells). Most buckets stay empty at crowd densities (several
// agents share a cell), and the scan and sort passes cost in proportion to it.
uint32_t gridCellCount(uint32_t agents);
inline constexpr uint32_t kMaxGridCells = 1u << 20;

// The grid: the same arrays the GPU passes fill, in the same order.
struct Grid {
  uint32_t cellCount = 0;
  float invCellSize = 0.0f;
  std::vector<uint32_t> cellOf;       // per agent: hashed cell
  std::vector<uint32_t> counts;       // per cell
  std::vector<uint32_t> starts;       // per cell: first slot (exclusive prefix sum of counts)
  std::vector<uint32_t> sortedIndex;  // per slot: agent, by cell then increasing index
  std::vector<glm::vec4> sorted;      // per slot: (x, z, vx, vz)
};

// placement = (x, y, z, heading); steer = (vx, vz, speed, flags); goals = (target x, z, max
// speed, active). Agents with goal.w == 0 are inactive: steer zero, nothing else changes.
Grid buildGridCpu(std::span<const glm::vec4> placement, std::span<const glm::vec4> steer, float cellSize,
                  uint32_t cellCount);
void steerCpu(const Grid& grid, const AvoidanceParams& params, const SteerFrame& frame,
              std::span<glm::vec4> placement, std::span<glm::vec4> motion, std::span<const glm::vec4> goals,
              std::span<glm::vec4> steer);
// position += velocity · dt for active agents (the kinematic integration of `throng crowd`).
void advanceCpu(std::span<glm::vec4> placement, std::span<const glm::vec4> steer, std::span<const glm::vec4> goals,
                float dt);

// The hashes of shaders/avoidance_common.glsl.
uint32_t pcgHash(uint32_t v);
glm::ivec2 cellCoord(glm::vec2 p, float invCellSize);
uint32_t cellHash(glm::ivec2 cell, uint32_t cellCount);
float steerRandom(uint32_t agent, uint32_t step, uint32_t seed);

}  // namespace throng::crowd
