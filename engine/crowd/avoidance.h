#pragma once
// Collision avoidance (docs/design.md, "Storyboard crowds"): each agent is a cylinder of a safe
// radius; every step a uniform grid is built by counting sort (count and rank per cell, exclusive
// prefix sum, scatter) and each agent looks at the agents of the nearby cells. Policies:
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
//     towards the waypoint velocity. Forces are summed in fixed point (crowd_types.h), so
//     the order neighbours are visited in does not matter.
// Under both policies the local density slows walkers (Weidmann's fundamental diagram, on by
// default; crowd_types.h): without it agents stream through a bottleneck several abreast at
// full speed, 2–3× the flow people manage.
// The output of a step is the heading (placement.w) and velocity/speed (steer) each agent
// takes, and its speed weight (motion.z, taken up by the root-motion pass at the cycle end).
// This file is the CPU twin; avoidance_jobs.h records the same passes on the GPU.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace throng::crowd {

struct WallGrid;  // crowd/obstacles.h

enum class SteerPolicy : uint32_t { None = 0, Rule = 1, Ttc = 2 };
// The one vocabulary of policies: "anticipatory" (time to collision), "published" (the rule)
// and "none"; "ttc" and "rule" are accepted as aliases. Names are the first three.
std::optional<SteerPolicy> parseSteerPolicy(std::string_view name);
std::string_view steerPolicyName(SteerPolicy policy);

struct AvoidanceParams {
  SteerPolicy policy = SteerPolicy::Ttc;
  // Grid cell (x width, z depth) in metres. Narrower than deep: a subgroup's lanes lie along a
  // row, and the union of their neighbourhoods overhangs their columns by the sensing distance
  // rounded out to whole cells, less with narrow cells (about 10% fewer candidates at 1.5 m).
  glm::vec2 cellSize{1.5f, 3.0f};
  float radius = 0.3f;        // safe radius of every cylinder (m)
  float sensing = 3.0f;       // neighbours farther than this are ignored (m)
  float lookahead = 1.0f;     // rule: seconds ahead the overlap is tested
  float gazeAngle = 1.5708f;  // rule: full width of the random turn (rad), 90°
  float ttcK = 1.5f;          // TTC constants of the paper: k, τ0 (s), relaxation ξ (s)
  float ttcTau0 = 3.0f;
  float ttcXi = 0.54f;
  float ttcMaxForce = 20.0f;  // cap of the avoidance acceleration (m/s²)
  // Density-dependent speed (both policies; crowd_types.h): the kernel radius R of the local
  // density (m, at most the sensing distance); 0 turns it off.
  float densityRadius = 1.5f;
  uint32_t seed = 1;
};
// Problems with the parameters (empty when valid).
std::vector<std::string> validateParams(const AvoidanceParams& params);
// Neighbour columns and rows scanned on each side: ceil(sensing / cellSize) per axis.
glm::ivec2 cellRange(const AvoidanceParams& params);

// Root speeds of one clip pair (speed → w) for the agents [previous set's end, end).
struct ClipSpeeds {
  float slow = 0.0f;
  float fast = 0.0f;
  uint32_t end = UINT32_MAX;
};

// What changes from step to step.
struct SteerFrame {
  float dt = 0.0f;           // seconds of this step
  float secondsLeft = 1.0f;  // until the current waypoint is due (> 0)
  uint32_t step = 0;         // hashed into the rule's random turn
  float slowSpeed = 0.0f;    // root speeds of the clip pair: speed → motion.z = w
  float fastSpeed = 0.0f;
  // With several clip pairs (the crowd ordered by clip set): up to kMaxClipSets ranges, each
  // with its pair's root speeds, used instead of slowSpeed/fastSpeed. A pair whose fast speed
  // is not above its slow one (standing clips) leaves motion.z alone.
  std::vector<ClipSpeeds> sets;
};
// The ranges the shader reads (sets, or one range of slowSpeed/fastSpeed); throws Error for
// more than kMaxClipSets sets or ends that decrease.
std::array<ClipSpeeds, 4> clipSpeedTable(const SteerFrame& frame);

// The grid table: 2^widthShift columns × (rowMask + 1) rows, cellCount cells in all (a power
// of two ≥ agents within [1024, 2^20]; at crowd densities most cells stay empty, and the scan
// costs in proportion to it). Cell coordinates are taken modulo the table.
struct GridTable {
  uint32_t cellCount = 0;
  uint32_t widthShift = 0;
  uint32_t rowMask = 0;
};
GridTable gridTable(uint32_t agents);
inline constexpr uint32_t kMaxGridCells = 1u << 20;

// The grid: the same arrays the GPU passes fill. Within a cell the GPU's order is its atomics'
// (any); the twin's is by agent index. Nothing downstream depends on that order.
struct Grid {
  GridTable table;
  glm::vec2 invCellSize{0.0f};
  std::vector<uint32_t> cellOf;  // per agent: cell index
  std::vector<uint32_t> counts;  // per cell
  std::vector<uint32_t>
      starts;  // per cell + 1: first slot (exclusive prefix sum), then the agent count
  std::vector<uint32_t> sortedIndex;  // per slot: agent, by cell
  std::vector<glm::vec4> sorted;      // per slot: (x, z, vx, vz)
};

// The agents in the order of the grid's slots (stably by cell), for numbering a crowd when it
// is spawned: neighbours in space are then neighbours in memory, so the passes that read and
// write per-agent buffers by agent index (steering, grid build, advance) touch few cache lines.
std::vector<uint32_t> gridOrder(std::span<const glm::vec4> placement, glm::vec2 cellSize,
                                GridTable table);

// placement = (x, y, z, heading); steer = (vx, vz, speed, flags); goals = (target x, z, max
// speed, active). Agents with goal.w == 0 are inactive: steer zero, nothing else changes.
Grid buildGridCpu(std::span<const glm::vec4> placement, std::span<const glm::vec4> steer,
                  glm::vec2 cellSize, GridTable table);
// `walls` (optional): static segments every policy but None treats as neighbours that never
// move (their lists must reach at least the sensing distance).
void steerCpu(const Grid& grid, const AvoidanceParams& params, const SteerFrame& frame,
              std::span<glm::vec4> placement, std::span<glm::vec4> motion,
              std::span<const glm::vec4> goals, std::span<glm::vec4> steer,
              const WallGrid* walls = nullptr);
// The density rule's push constants (1 / R², 6 / (π R²)), zero when it is off, and the helpers
// of shaders/avoidance_common.glsl: the fixed-point kernel weight of a neighbour at x = own
// position − its position (dist2 = |x|²) for an agent heading along dir, and Weidmann's speed
// fraction for a sum of weights.
glm::vec2 densityPush(const AvoidanceParams& params);
uint32_t densityWeight(glm::vec2 x, float dist2, glm::vec2 dir, float invRadius2);
float densitySpeedFactor(uint32_t weights, float norm);
// position += velocity · dt for active agents (the kinematic integration of `throng crowd`).
void advanceCpu(std::span<glm::vec4> placement, std::span<const glm::vec4> steer,
                std::span<const glm::vec4> goals, float dt);

// The helpers of shaders/avoidance_common.glsl.
uint32_t pcgHash(uint32_t v);
glm::ivec2 cellCoord(glm::vec2 p, glm::vec2 invCellSize);
uint32_t cellIndex(glm::ivec2 cell, const GridTable& table);
float steerRandom(uint32_t agent, uint32_t step, uint32_t seed);

}  // namespace throng::crowd
