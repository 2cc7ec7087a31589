#pragma once
// The grid, steering and kinematic-advance passes as jobs (like synth/synth_jobs.h): named
// inputs and outputs, validate() listing what is missing or inconsistent, record() that
// checks and records. Per step: GridJob, barrier, AvoidanceJob, barrier, then either
// AdvanceJob (kinematic, `throng crowd`) or the synthesis RootMotionJob (render path), which
// moves each character along the heading the avoidance job wrote. CPU twins: avoidance.h.
#include <map>
#include <memory>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "crowd/avoidance.h"
#include "crowd/crowd.h"
#include "crowd/obstacles.h"
#include "gpu/program.h"
#include "gpu/timestamps.h"

namespace throng::crowd {

// The compiled passes. The steering pass is specialized per (policy, neighbour range), built
// on first use; subgroups of at least 4 lanes with vote, arithmetic and ballot are required
// (lavapipe: 8; every desktop GPU has them).
struct WallBuffers;

class AvoidancePrograms {
 public:
  explicit AvoidancePrograms(const gpu::Context& context);
  ~AvoidancePrograms();
  gpu::ComputeProgram count, scan, scatter, advance, goals, wallConstraint;
  gpu::ComputeProgram wallAdvance;  // wall_constraint.comp in its moving form
  const gpu::ComputeProgram& steer(SteerPolicy policy, glm::ivec2 range, bool walls = false) const;
  uint32_t chunk() const { return chunk_; }  // candidates shared per subgroup round
  // Empty walls, bound where a pass runs without walls (every declared binding must be given).
  const WallBuffers& noWalls() const;

 private:
  const gpu::Context* context_;
  uint32_t chunk_ = 8;
  mutable std::map<std::tuple<uint32_t, int, int, bool>, std::unique_ptr<gpu::ComputeProgram>>
      steer_;
  mutable std::unique_ptr<WallBuffers> noWalls_;
};

// A WallGrid on the GPU: its frame as a uniform block, segments (RGBA32F), starts and indices
// (R32UI) as texels. Uploaded once: walls do not move.
struct WallBuffers {
  // segments: the segments themselves (drawn by the renderer); entries: per entry of the cells'
  // lists its segment, copied in list order, so the passes read a list with one fetch per entry
  // instead of an index and then the segment it names.
  gpu::Buffer info, segments, starts, entries, clearance;
  gpu::Handle<VkBufferView> segmentTexels, startTexels, entryTexels, clearanceTexels;
  float reach = 0.0f;  // the grid's lists hold every segment within this of their cell
  uint32_t segmentCount = 0;
};
WallBuffers uploadWalls(const gpu::Context& context, const WallGrid& walls);

// Each agent's placement before a step, the input of WallConstraintJob (RGBA32F texels).
struct SavedPositions {
  gpu::Buffer placement;
  gpu::Handle<VkBufferView> texels;
  uint32_t capacity = 0;
};
SavedPositions makeSavedPositions(const gpu::Context& context, uint32_t capacity);
// Copies the placement of agents [first, first + count) into `saved` (a transfer; barriers from
// earlier compute writes and to later compute reads).
void recordSavePositions(VkCommandBuffer cmd, const CrowdBuffers& crowd,
                         const SavedPositions& saved, uint32_t first, uint32_t count);

// The grid's GPU arrays (Grid in avoidance.h), sized for up to `agentCapacity` agents.
struct GridBuffers {
  gpu::Buffer cellRank, counts, starts, sortedIndex, sorted;
  // What the passes read, as texels (lavapipe gathers texels, loops over lanes for
  // storage-buffer loads): `cellRank` as RG32UI, `counts` as RGBA32UI (four cells a texel),
  // `starts` and `sortedIndex` as R32UI, `sorted` as RGBA32F.
  gpu::Handle<VkBufferView> cellRankTexels, countTexels, startTexels, sortedIndexTexels,
      sortedTexels;
  uint32_t agentCapacity = 0;
  GridTable table;
  glm::vec2 cellSize{0.0f};  // x width, z depth (m)
};
GridBuffers makeGridBuffers(const gpu::Context& context, uint32_t agentCapacity,
                            glm::vec2 cellSize);

// Per-agent steering arrays beside CrowdBuffers: goal (target x, z, max speed, active) and
// steer (vx, vz, speed, flags).
struct SteerBuffers {
  gpu::Buffer goals;
  gpu::Buffer steer;
  // `goals` and `steer` as RGBA32F texels, for the steering pass and the grid build
  gpu::Handle<VkBufferView> goalTexels, steerTexels;
  uint32_t count = 0;
};
SteerBuffers uploadSteer(const gpu::Context& context, std::span<const glm::vec4> goals,
                         std::span<const glm::vec4> steer);

// Counting sort of the agents into the grid: clear, count (cell and rank per agent), scan,
// scatter of the agent index and a copy of (x, z, vx, vz). Barriers between its own passes.
struct GridJob {
  const CrowdBuffers* crowd = nullptr;   // input: placement
  const SteerBuffers* agents = nullptr;  // input: steer (velocities copied into the grid)
  const GridBuffers* grid = nullptr;     // output
  // Optional: a mark after the count, the scan and the scatter.
  gpu::TimestampPool* timestamps = nullptr;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const;
};

// Path-vector steering + avoidance: reads goals, the grid and each agent's previous velocity;
// writes placement.w (heading), steer and motion.z (wTarget).
struct AvoidanceJob {
  const CrowdBuffers* crowd = nullptr;   // input/output: placement (heading), motion (wTarget)
  const SteerBuffers* agents = nullptr;  // input: goals; input/output: steer
  const GridBuffers* grid = nullptr;     // input: built this step by GridJob
  AvoidanceParams params;
  SteerFrame frame;
  // Optional static walls (reach >= params.sensing), neighbours that never move.
  const WallBuffers* walls = nullptr;

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const;
};

// position += velocity · dt for active agents (twin: advanceCpu). With walls, the move is
// constrained in the same pass as WallConstraintJob constrains a saved move (twin: advanceCpu,
// then wallConstraintCpu): no saved positions and no second pass.
struct AdvanceJob {
  const CrowdBuffers* crowd = nullptr;   // input/output: placement
  const SteerBuffers* agents = nullptr;  // input: steer, goals
  float dt = 0.0f;
  const WallBuffers* walls = nullptr;  // optional
  float radius = 0.3f;                 // with walls: the safe radius kept from them

  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const;

 private:
  void recordWalled(VkCommandBuffer cmd, const AvoidancePrograms& programs) const;
};

// The hard guarantee of static walls (shaders/wall_constraint.comp; twin: wallConstraintCpu):
// each agent of [firstCharacter, firstCharacter + count) moved from `previous` to its placement
// now is stopped at its first contact with a wall and slid along it, so no agent crosses a
// segment or ends within `radius` of one. Record it after whatever moved the agents (AdvanceJob,
// or root motion), with recordSavePositions before that move; only placement.xz changes.
struct WallConstraintJob {
  const CrowdBuffers* crowd = nullptr;       // input/output: placement
  const SavedPositions* previous = nullptr;  // input: placement before the move
  const WallBuffers* walls = nullptr;
  float radius = 0.3f;
  uint32_t firstCharacter = 0;
  uint32_t count = UINT32_MAX;  // UINT32_MAX: to the end of the crowd

  uint32_t agents() const;  // count resolved
  std::vector<std::string> validate() const;
  void record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const;
};

}  // namespace throng::crowd
