#include "crowd/avoidance_jobs.h"

#include <cmath>

#include "core/error.h"
#include "crowd/avoidance_types.h"
#include "gpu/commands.h"

namespace throng::crowd {
namespace {

void throwIfInvalid(const std::string& job, const std::vector<std::string>& problems) {
  if (problems.empty()) return;
  std::string message = job + " is invalid:";
  for (const std::string& p : problems) message += "\n  - " + p;
  throw Error(message);
}

void requireBuffer(std::vector<std::string>& problems, const gpu::Buffer& buffer, VkDeviceSize need,
                   const char* name) {
  if (!buffer) problems.push_back(concat("buffer '", name, "' is not allocated"));
  else if (buffer.size() < need)
    problems.push_back(concat("buffer '", name, "' holds ", buffer.size(), " bytes, ", need, " needed"));
}

void checkCrowdAndAgents(std::vector<std::string>& problems, const CrowdBuffers* crowd, const SteerBuffers* agents) {
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  if (!agents) problems.push_back("input 'agents' (goal and steer buffers) are missing");
  if (!crowd || !agents) return;
  const VkDeviceSize bytes = VkDeviceSize(crowd->count) * sizeof(glm::vec4);
  requireBuffer(problems, crowd->placement, bytes, "placement");
  requireBuffer(problems, crowd->motion, bytes, "motion");
  if (agents->count != crowd->count)
    problems.push_back(concat("the crowd has ", crowd->count, " agents but the steering buffers ", agents->count));
  requireBuffer(problems, agents->goals, bytes, "goals");
  requireBuffer(problems, agents->steer, bytes, "steer");
}

void checkGrid(std::vector<std::string>& problems, const GridBuffers* grid, const CrowdBuffers* crowd) {
  if (!grid) {
    problems.push_back("grid buffers are missing");
    return;
  }
  if (crowd && crowd->count > grid->agentCapacity)
    problems.push_back(concat("the grid holds ", grid->agentCapacity, " agents, the crowd has ", crowd->count));
  if (grid->cellCount == 0 || (grid->cellCount & (grid->cellCount - 1)) || grid->cellCount > kMaxGridCells)
    problems.push_back(concat("grid cell count ", grid->cellCount, " is not a power of two up to ", kMaxGridCells));
  if (!(grid->cellSize > 0.0f)) problems.push_back(concat("grid cell size must be positive, got ", grid->cellSize));
}

GridPush gridPush(const GridBuffers& grid, uint32_t agents) {
  GridPush push{};
  push.agentCount = agents;
  push.cellCount = grid.cellCount;
  push.blockCount = (grid.cellCount + kScanBlock - 1) / kScanBlock;
  push.invCellSize = 1.0f / grid.cellSize;
  return push;
}

}  // namespace

AvoidancePrograms::AvoidancePrograms(const gpu::Context& context)
    : count(context, "avoidance_grid_count.comp"),
      scanBlocks(context, "avoidance_scan_blocks.comp"),
      scanSums(context, "avoidance_scan_sums.comp"),
      scanAdd(context, "avoidance_scan_add.comp"),
      scatter(context, "avoidance_scatter.comp"),
      cellSort(context, "avoidance_cell_sort.comp"),
      gather(context, "avoidance_gather.comp"),
      steer(context, "avoidance_steer.comp"),
      advance(context, "avoidance_advance.comp") {}

GridBuffers makeGridBuffers(const gpu::Context& context, uint32_t agentCapacity, float cellSize) {
  if (!(cellSize > 0.0f)) fail("grid cell size must be positive, got ", cellSize);
  GridBuffers g;
  g.agentCapacity = std::max(agentCapacity, 1u);
  g.cellCount = gridCellCount(agentCapacity);
  g.cellSize = cellSize;
  const uint32_t blocks = (g.cellCount + kScanBlock - 1) / kScanBlock;
  auto make = [&](VkDeviceSize bytes) {
    return gpu::Buffer(context, std::max<VkDeviceSize>(bytes, 16), gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  };
  g.cellOf = make(VkDeviceSize(g.agentCapacity) * 4);
  g.counts = make(VkDeviceSize(g.cellCount) * 4);
  g.starts = make(VkDeviceSize(g.cellCount) * 4);
  g.blockSums = make(VkDeviceSize(blocks) * 4);
  g.cursor = make(VkDeviceSize(g.cellCount) * 4);
  g.sortedIndex = make(VkDeviceSize(g.agentCapacity) * 4);
  g.sorted = make(VkDeviceSize(g.agentCapacity) * sizeof(glm::vec4));
  return g;
}

SteerBuffers uploadSteer(const gpu::Context& context, std::span<const glm::vec4> goals,
                         std::span<const glm::vec4> steer) {
  if (goals.size() != steer.size()) fail("uploadSteer: ", goals.size(), " goals but ", steer.size(), " steer entries");
  SteerBuffers b;
  b.count = uint32_t(goals.size());
  b.goals = gpu::makeStorageBuffer<glm::vec4>(context, goals);
  b.steer = gpu::makeStorageBuffer<glm::vec4>(context, steer);
  return b;
}

std::vector<std::string> GridJob::validate() const {
  std::vector<std::string> problems;
  checkCrowdAndAgents(problems, crowd, agents);
  checkGrid(problems, grid, crowd);
  return problems;
}

void GridJob::record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const {
  throwIfInvalid("GridJob", validate());
  const GridPush push = gridPush(*grid, crowd->count);
  const VkDeviceSize cellBytes = VkDeviceSize(grid->cellCount) * 4;
  vkCmdFillBuffer(cmd, grid->counts.get(), 0, cellBytes, 0);
  vkCmdFillBuffer(cmd, grid->cursor.get(), 0, cellBytes, 0);
  gpu::computeToComputeBarrier(cmd);
  const gpu::Binding count[] = {gpu::storageBinding(0, crowd->placement), gpu::storageBinding(1, grid->cellOf),
                                gpu::storageBinding(2, grid->counts)};
  gpu::dispatch(cmd, programs.count, count, push, crowd->count);
  gpu::computeToComputeBarrier(cmd);
  const gpu::Binding blocks[] = {gpu::storageBinding(0, grid->counts), gpu::storageBinding(1, grid->starts),
                                 gpu::storageBinding(2, grid->blockSums)};
  gpu::dispatch(cmd, programs.scanBlocks, blocks, push, push.blockCount * 256);
  gpu::computeToComputeBarrier(cmd);
  const gpu::Binding sums[] = {gpu::storageBinding(0, grid->blockSums)};
  gpu::dispatch(cmd, programs.scanSums, sums, push, 256);
  gpu::computeToComputeBarrier(cmd);
  const gpu::Binding add[] = {gpu::storageBinding(0, grid->starts), gpu::storageBinding(1, grid->blockSums)};
  gpu::dispatch(cmd, programs.scanAdd, add, push, grid->cellCount);
  gpu::computeToComputeBarrier(cmd);
  const gpu::Binding scatter[] = {gpu::storageBinding(0, grid->cellOf), gpu::storageBinding(1, grid->starts),
                                  gpu::storageBinding(2, grid->cursor), gpu::storageBinding(3, grid->sortedIndex)};
  gpu::dispatch(cmd, programs.scatter, scatter, push, crowd->count);
  gpu::computeToComputeBarrier(cmd);
  const gpu::Binding sort[] = {gpu::storageBinding(0, grid->counts), gpu::storageBinding(1, grid->starts),
                               gpu::storageBinding(2, grid->sortedIndex)};
  gpu::dispatch(cmd, programs.cellSort, sort, push, grid->cellCount);
  gpu::computeToComputeBarrier(cmd);
  const gpu::Binding gather[] = {gpu::storageBinding(0, crowd->placement), gpu::storageBinding(1, agents->steer),
                                 gpu::storageBinding(2, grid->sortedIndex), gpu::storageBinding(3, grid->sorted)};
  gpu::dispatch(cmd, programs.gather, gather, push, crowd->count);
}

std::vector<std::string> AvoidanceJob::validate() const {
  std::vector<std::string> problems;
  checkCrowdAndAgents(problems, crowd, agents);
  checkGrid(problems, grid, crowd);
  for (const std::string& p : validateParams(params)) problems.push_back(p);
  if (grid && grid->cellSize != params.cellSize)
    problems.push_back(concat("the grid was built with ", grid->cellSize, " m cells, the parameters say ",
                              params.cellSize, " m"));
  if (!(frame.dt >= 0.0f)) problems.push_back(concat("dt must be >= 0, got ", frame.dt));
  if (!(frame.secondsLeft > 0.0f)) problems.push_back(concat("secondsLeft must be > 0, got ", frame.secondsLeft));
  return problems;
}

void AvoidanceJob::record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const {
  throwIfInvalid("AvoidanceJob", validate());
  SteerPush push{};
  push.agentCount = crowd->count;
  push.cellCount = grid->cellCount;
  push.policy = uint32_t(params.policy);
  push.step = frame.step;
  push.seed = params.seed;
  push.cellRange = cellRange(params);
  push.invCellSize = 1.0f / grid->cellSize;
  push.dt = frame.dt;
  push.invSecondsLeft = 1.0f / frame.secondsLeft;
  push.radius = params.radius;
  push.sensing = params.sensing;
  push.lookahead = params.lookahead;
  push.gazeAngle = params.gazeAngle;
  push.ttcK = params.ttcK;
  push.ttcTau0 = params.ttcTau0;
  push.ttcXi = params.ttcXi;
  push.ttcMaxForce = params.ttcMaxForce;
  push.slowSpeed = frame.slowSpeed;
  push.fastSpeed = frame.fastSpeed;
  push.cosHalfGaze = std::cos(0.5f * params.gazeAngle);
  const gpu::Binding bindings[] = {
      gpu::storageBinding(0, crowd->placement), gpu::storageBinding(1, crowd->motion),
      gpu::storageBinding(2, agents->goals),    gpu::storageBinding(3, agents->steer),
      gpu::storageBinding(4, grid->counts),     gpu::storageBinding(5, grid->starts),
      gpu::storageBinding(6, grid->sortedIndex), gpu::storageBinding(7, grid->sorted)};
  gpu::dispatch(cmd, programs.steer, bindings, push, crowd->count);
}

std::vector<std::string> AdvanceJob::validate() const {
  std::vector<std::string> problems;
  checkCrowdAndAgents(problems, crowd, agents);
  if (!(dt >= 0.0f)) problems.push_back(concat("dt must be >= 0, got ", dt));
  return problems;
}

void AdvanceJob::record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const {
  throwIfInvalid("AdvanceJob", validate());
  AdvancePush push{};
  push.agentCount = crowd->count;
  push.dt = dt;
  const gpu::Binding bindings[] = {gpu::storageBinding(0, crowd->placement), gpu::storageBinding(1, agents->steer),
                                   gpu::storageBinding(2, agents->goals)};
  gpu::dispatch(cmd, programs.advance, bindings, push, crowd->count);
}

}  // namespace throng::crowd
