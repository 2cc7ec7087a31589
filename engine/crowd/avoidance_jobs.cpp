#include "crowd/avoidance_jobs.h"

#include <array>

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "crowd/avoidance_types.h"
#include "gpu/commands.h"
#include "gpu/job_check.h"
#include "shaders/crowd_bindings.h"

namespace throng::crowd {
namespace {

void requireBuffer(std::vector<std::string>& problems, const gpu::Buffer& buffer, VkDeviceSize need,
                   const char* name) {
  if (!buffer)
    problems.push_back(concat("buffer '", name, "' is not allocated"));
  else if (buffer.size() < need)
    problems.push_back(
        concat("buffer '", name, "' holds ", buffer.size(), " bytes, ", need, " needed"));
}

void checkCrowdAndAgents(std::vector<std::string>& problems, const CrowdBuffers* crowd,
                         const SteerBuffers* agents) {
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  if (!agents) problems.push_back("input 'agents' (goal and steer buffers) are missing");
  if (!crowd || !agents) return;
  const VkDeviceSize bytes = VkDeviceSize(crowd->count) * sizeof(glm::vec4);
  requireBuffer(problems, crowd->placement, bytes, "placement");
  requireBuffer(problems, crowd->motion, bytes, "motion");
  if (agents->count != crowd->count)
    problems.push_back(
        concat("the crowd has ", crowd->count, " agents but the steering buffers ", agents->count));
  requireBuffer(problems, agents->goals, bytes, "goals");
  requireBuffer(problems, agents->steer, bytes, "steer");
  if (!crowd->placementTexels || !agents->goalTexels || !agents->steerTexels)
    problems.push_back(
        "texel views of placement, goals or steer are missing (make the buffers with uploadCrowd "
        "and uploadSteer)");
}

void checkGrid(std::vector<std::string>& problems, const GridBuffers* grid,
               const CrowdBuffers* crowd) {
  if (!grid) {
    problems.push_back("grid buffers are missing");
    return;
  }
  if (crowd && crowd->count > grid->agentCapacity)
    problems.push_back(
        concat("the grid holds ", grid->agentCapacity, " agents, the crowd has ", crowd->count));
  const GridTable& t = grid->table;
  if (t.cellCount == 0 || t.cellCount > kMaxGridCells ||
      t.cellCount != (t.rowMask + 1u) << t.widthShift || ((t.rowMask + 1u) & t.rowMask) != 0 ||
      t.rowMask < 31u || t.widthShift < 5u)
    problems.push_back(concat("grid table of ", t.cellCount, " cells (", 1u << t.widthShift, " x ",
                              t.rowMask + 1u, ") is not powers of two of at least 32 x 32 up to ",
                              kMaxGridCells, " cells"));
  if (!grid->cellRankTexels || !grid->countTexels || !grid->startTexels ||
      !grid->sortedIndexTexels || !grid->sortedTexels)
    problems.push_back("the grid's texel views are missing (make it with makeGridBuffers)");
  if (!(grid->cellSize.x > 0.0f && grid->cellSize.y > 0.0f))
    problems.push_back(concat("grid cells must have a positive size, got ", grid->cellSize.x, " x ",
                              grid->cellSize.y, " m"));
}

GridPush gridPush(const GridBuffers& grid, uint32_t agents) {
  GridPush push{};
  push.agentCount = agents;
  push.cellCount = grid.table.cellCount;
  push.widthShift = grid.table.widthShift;
  push.rowMask = grid.table.rowMask;
  push.invCellX = 1.0f / grid.cellSize.x;
  push.invCellZ = 1.0f / grid.cellSize.y;
  return push;
}

// Subgroup lanes the steering pass shares candidates among; throws when the device's subgroups
// lack what the pass uses.
uint32_t subgroupChunk(const gpu::Context& context) {
  const gpu::DeviceInfo& info = context.info();
  const VkSubgroupFeatureFlags needed =
      VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_VOTE_BIT |
      VK_SUBGROUP_FEATURE_ARITHMETIC_BIT | VK_SUBGROUP_FEATURE_SHUFFLE_BIT;
  if ((info.computeSubgroupOperations & needed) != needed || info.subgroupSize < 4)
    fail(
        "the steering pass needs compute subgroups of at least 4 lanes with vote, arithmetic and "
        "shuffle; ",
        info.name, " has ", info.subgroupSize, " lanes, compute operations 0x", std::hex,
        info.computeSubgroupOperations);
  return std::min(info.subgroupSize, 32u);
}

}  // namespace

AvoidancePrograms::AvoidancePrograms(const gpu::Context& context)
    : count(context, "avoidance_grid_count.comp"),
      scan(context, "avoidance_scan.comp"),
      scatter(context, "avoidance_scatter.comp"),
      advance(context, "avoidance_advance.comp"),
      goals(context, "path_goals.comp"),
      wallConstraint(context, "wall_constraint.comp"),
      wallAdvance(context, "wall_constraint.comp", std::array<uint32_t, 1>{1u}),
      context_(&context),
      chunk_(subgroupChunk(context)) {}

AvoidancePrograms::~AvoidancePrograms() = default;

const WallBuffers& AvoidancePrograms::noWalls() const {
  if (!noWalls_) noWalls_ = std::make_unique<WallBuffers>(uploadWalls(*context_, WallGrid{}));
  return *noWalls_;
}

const gpu::ComputeProgram& AvoidancePrograms::steer(SteerPolicy policy, glm::ivec2 range,
                                                    bool walls) const {
  std::unique_ptr<gpu::ComputeProgram>& program =
      steer_[{uint32_t(policy), range.x, range.y, walls}];
  if (!program) {
    uint32_t specialization[gpu_types::kSteerConstantCount] = {};
    specialization[gpu_types::kSteerConstantPolicy] = uint32_t(policy);
    specialization[gpu_types::kSteerConstantRange] = uint32_t(range.x);
    specialization[gpu_types::kSteerConstantChunk] = chunk_;
    specialization[gpu_types::kSteerConstantRangeZ] = uint32_t(range.y);
    specialization[gpu_types::kSteerConstantWalls] = walls ? 1u : 0u;
    program =
        std::make_unique<gpu::ComputeProgram>(*context_, "avoidance_steer.comp", specialization);
  }
  return *program;
}

GridBuffers makeGridBuffers(const gpu::Context& context, uint32_t agentCapacity,
                            glm::vec2 cellSize) {
  if (!(cellSize.x > 0.0f && cellSize.y > 0.0f))
    fail("grid cells must have a positive size, got ", cellSize.x, " x ", cellSize.y, " m");
  GridBuffers g;
  g.agentCapacity = std::max(agentCapacity, 1u);
  g.table = gridTable(agentCapacity);
  g.cellSize = cellSize;
  auto make = [&](VkDeviceSize bytes, VkBufferUsageFlags extraUsage = 0) {
    return gpu::Buffer(context, std::max<VkDeviceSize>(bytes, 16), gpu::kStorageUsage | extraUsage,
                       gpu::MemoryUse::DeviceLocal);
  };
  const VkBufferUsageFlags texels = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
  g.cellRank = make(VkDeviceSize(g.agentCapacity) * 8, texels);
  g.counts = make(VkDeviceSize(g.table.cellCount) * 4, texels);
  g.starts = make(VkDeviceSize(g.table.cellCount + 1) * 4, texels);
  g.sortedIndex = make(VkDeviceSize(g.agentCapacity) * 4, texels);
  g.sorted = make(VkDeviceSize(g.agentCapacity) * sizeof(glm::vec4), texels);
  g.cellRankTexels = gpu::makeBufferView(context, g.cellRank, VK_FORMAT_R32G32_UINT);
  g.countTexels = gpu::makeBufferView(context, g.counts, VK_FORMAT_R32G32B32A32_UINT);
  g.startTexels = gpu::makeBufferView(context, g.starts, VK_FORMAT_R32_UINT);
  g.sortedIndexTexels = gpu::makeBufferView(context, g.sortedIndex, VK_FORMAT_R32_UINT);
  g.sortedTexels = gpu::makeBufferView(context, g.sorted, VK_FORMAT_R32G32B32A32_SFLOAT);
  return g;
}

SteerBuffers uploadSteer(const gpu::Context& context, std::span<const glm::vec4> goals,
                         std::span<const glm::vec4> steer) {
  if (goals.size() != steer.size())
    fail("uploadSteer: ", goals.size(), " goals but ", steer.size(), " steer entries");
  SteerBuffers b;
  b.count = uint32_t(goals.size());
  b.goals = gpu::makeStorageBuffer<glm::vec4>(context, goals, gpu::MemoryUse::DeviceLocal,
                                              VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
  b.goalTexels = gpu::makeBufferView(context, b.goals, VK_FORMAT_R32G32B32A32_SFLOAT);
  b.steer = gpu::makeStorageBuffer<glm::vec4>(context, steer, gpu::MemoryUse::DeviceLocal,
                                              VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
  b.steerTexels = gpu::makeBufferView(context, b.steer, VK_FORMAT_R32G32B32A32_SFLOAT);
  return b;
}

WallBuffers uploadWalls(const gpu::Context& context, const WallGrid& walls) {
  if (walls.starts.size() != size_t(walls.columns) * walls.rows + 1 && !walls.starts.empty())
    fail("uploadWalls: ", walls.starts.size(), " cell starts for ", walls.columns, " x ",
         walls.rows, " cells");
  WallBuffers b;
  b.reach = walls.reach;
  b.segmentCount = uint32_t(walls.segments.size());
  WallGridInfo info{};
  info.frame = glm::vec4(walls.origin, 1.0f / walls.cellSize, walls.reach);
  // An empty grid (no cells) keeps columns 0: every point lies outside it.
  const bool any = !walls.starts.empty();
  info.size = glm::uvec4(any ? walls.columns : 0u, any ? walls.rows : 0u, b.segmentCount, 0u);
  b.info = gpu::Buffer(context, sizeof(WallGridInfo),
                       VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                       gpu::MemoryUse::DeviceLocal);
  gpu::uploadBytes(context, b.info, {reinterpret_cast<const uint8_t*>(&info), sizeof(info)});
  static_assert(sizeof(Segment) == sizeof(glm::vec4));
  const std::vector<uint32_t> noStarts = {0u, 0u};
  const VkBufferUsageFlags texels = VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
  b.segments =
      gpu::makeStorageBuffer<Segment>(context, walls.segments, gpu::MemoryUse::DeviceLocal, texels);
  b.starts = gpu::makeStorageBuffer<uint32_t>(context, any ? walls.starts : noStarts,
                                              gpu::MemoryUse::DeviceLocal, texels);
  std::vector<Segment> entries;
  entries.reserve(walls.indices.size());
  for (uint32_t k : walls.indices) entries.push_back(walls.segments.at(k));
  b.entries =
      gpu::makeStorageBuffer<Segment>(context, entries, gpu::MemoryUse::DeviceLocal, texels);
  const std::vector<float> noClearance = {0.0f};
  b.clearance = gpu::makeStorageBuffer<float>(
      context, walls.clearance.empty() ? noClearance : walls.clearance, gpu::MemoryUse::DeviceLocal,
      texels);
  b.clearanceTexels = gpu::makeBufferView(context, b.clearance, VK_FORMAT_R32_SFLOAT);
  b.segmentTexels = gpu::makeBufferView(context, b.segments, VK_FORMAT_R32G32B32A32_SFLOAT);
  b.startTexels = gpu::makeBufferView(context, b.starts, VK_FORMAT_R32_UINT);
  b.entryTexels = gpu::makeBufferView(context, b.entries, VK_FORMAT_R32G32B32A32_SFLOAT);
  return b;
}

SavedPositions makeSavedPositions(const gpu::Context& context, uint32_t capacity) {
  SavedPositions s;
  s.capacity = capacity;
  s.placement = gpu::Buffer(context, std::max<VkDeviceSize>(VkDeviceSize(capacity) * 16, 16),
                            gpu::kStorageUsage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                            gpu::MemoryUse::DeviceLocal);
  s.texels = gpu::makeBufferView(context, s.placement, VK_FORMAT_R32G32B32A32_SFLOAT);
  return s;
}

void recordSavePositions(VkCommandBuffer cmd, const CrowdBuffers& crowd,
                         const SavedPositions& saved, uint32_t first, uint32_t count) {
  if (size_t(first) + count > crowd.count || size_t(first) + count > saved.capacity)
    fail("recordSavePositions: agents ", first, " + ", count, " of a crowd of ", crowd.count,
         " and ", saved.capacity, " saved places");
  if (count == 0) return;
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  const VkBufferCopy region{VkDeviceSize(first) * 16, VkDeviceSize(first) * 16,
                            VkDeviceSize(count) * 16};
  vkCmdCopyBuffer(cmd, crowd.placement.get(), saved.placement.get(), 1, &region);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
}

std::vector<std::string> GridJob::validate() const {
  std::vector<std::string> problems;
  checkCrowdAndAgents(problems, crowd, agents);
  checkGrid(problems, grid, crowd);
  return problems;
}

void GridJob::record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const {
  gpu::throwIfInvalid("GridJob", validate());
  const GridPush push = gridPush(*grid, crowd->count);
  // The previous step's scan may still read the counts.
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  vkCmdFillBuffer(cmd, grid->counts.get(), 0, VkDeviceSize(grid->table.cellCount) * 4, 0);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  const gpu::Binding count[] = {
      gpu::uniformTexelBinding(gpu_types::kGridCountBindingPlacement, crowd->placementTexels),
      gpu::storageBinding(gpu_types::kGridCountBindingCellRank, grid->cellRank),
      gpu::storageBinding(gpu_types::kGridCountBindingCounts, grid->counts)};
  gpu::dispatch(cmd, programs.count, count, push, crowd->count);
  if (timestamps) timestamps->write(cmd);
  gpu::computeToComputeBarrier(cmd);
  const gpu::Binding scan[] = {
      gpu::uniformTexelBinding(gpu_types::kGridScanBindingCounts, grid->countTexels),
      gpu::storageBinding(gpu_types::kGridScanBindingStarts, grid->starts)};
  gpu::dispatch(cmd, programs.scan, scan, push, gpu_types::kScanThreads);
  if (timestamps) timestamps->write(cmd);
  gpu::computeToComputeBarrier(cmd);
  const gpu::Binding scatter[] = {
      gpu::uniformTexelBinding(gpu_types::kGridScatterBindingPlacement, crowd->placementTexels),
      gpu::uniformTexelBinding(gpu_types::kGridScatterBindingSteer, agents->steerTexels),
      gpu::uniformTexelBinding(gpu_types::kGridScatterBindingCellRank, grid->cellRankTexels),
      gpu::uniformTexelBinding(gpu_types::kGridScatterBindingStarts, grid->startTexels),
      gpu::storageBinding(gpu_types::kGridScatterBindingSortedIndex, grid->sortedIndex),
      gpu::storageBinding(gpu_types::kGridScatterBindingSorted, grid->sorted)};
  gpu::dispatch(cmd, programs.scatter, scatter, push, crowd->count);
  if (timestamps) timestamps->write(cmd);
}

std::vector<std::string> AvoidanceJob::validate() const {
  std::vector<std::string> problems;
  checkCrowdAndAgents(problems, crowd, agents);
  checkGrid(problems, grid, crowd);
  for (const std::string& p : validateParams(params)) problems.push_back(p);
  try {
    clipSpeedTable(frame);
  } catch (const Error& e) {
    problems.push_back(e.what());
  }
  if (grid && grid->cellSize != params.cellSize)
    problems.push_back(concat("the grid was built with ", grid->cellSize.x, " x ", grid->cellSize.y,
                              " m cells, the parameters say ", params.cellSize.x, " x ",
                              params.cellSize.y, " m"));
  if (!(frame.dt >= 0.0f)) problems.push_back(concat("dt must be >= 0, got ", frame.dt));
  if (!(frame.secondsLeft > 0.0f))
    problems.push_back(concat("secondsLeft must be > 0, got ", frame.secondsLeft));
  if (walls && !(walls->reach >= params.sensing))
    problems.push_back(concat("the walls were binned to reach ", walls->reach,
                              " m, less than the sensing distance ", params.sensing, " m"));
  if (walls && (!walls->info || !walls->segmentTexels || !walls->startTexels ||
                !walls->entryTexels || !walls->clearanceTexels))
    problems.push_back("the walls' buffers are missing (make them with uploadWalls)");
  return problems;
}

void AvoidanceJob::record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const {
  gpu::throwIfInvalid("AvoidanceJob", validate());
  SteerPush push{};
  push.agentCount = crowd->count;
  push.step = frame.step;
  push.seed = params.seed;
  push.widthShift = grid->table.widthShift;
  push.rowMask = grid->table.rowMask;
  push.invCellX = 1.0f / grid->cellSize.x;
  push.invCellZ = 1.0f / grid->cellSize.y;
  push.dt = frame.dt;
  push.invSecondsLeft = 1.0f / frame.secondsLeft;
  push.radius = params.radius;
  push.sensing = params.sensing;
  push.lookahead = params.lookahead;
  push.gazeAngle = params.gazeAngle;
  push.cosHalfGaze = std::cos(0.5f * params.gazeAngle);
  push.ttcK = params.ttcK;
  push.densityInvRadius2 = densityPush(params).x;
  push.densityNorm = densityPush(params).y;
  push.ttcXi = params.ttcXi;
  push.ttcMaxForce = params.ttcMaxForce;
  push.ttcInvTau0 = 1.0f / params.ttcTau0;
  const std::array<ClipSpeeds, 4> sets = clipSpeedTable(frame);
  for (int k = 0; k < 4; ++k) {
    push.setEnd[k] = sets[size_t(k)].end;
    push.setSlow[k] = sets[size_t(k)].slow;
    push.setFast[k] = sets[size_t(k)].fast;
  }
  const WallBuffers& w = walls ? *walls : programs.noWalls();
  const gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kSteerBindingPlacement, crowd->placement),
      gpu::storageBinding(gpu_types::kSteerBindingMotion, crowd->motion),
      gpu::uniformTexelBinding(gpu_types::kSteerBindingGoals, agents->goalTexels),
      gpu::storageBinding(gpu_types::kSteerBindingSteer, agents->steer),
      gpu::uniformTexelBinding(gpu_types::kSteerBindingStarts, grid->startTexels),
      gpu::uniformTexelBinding(gpu_types::kSteerBindingSortedIndex, grid->sortedIndexTexels),
      gpu::uniformTexelBinding(gpu_types::kSteerBindingSorted, grid->sortedTexels),
      gpu::uniformTexelBinding(gpu_types::kSteerBindingPlacementTexels, crowd->placementTexels),
      gpu::uniformTexelBinding(gpu_types::kSteerBindingSteerTexels, agents->steerTexels),
      gpu::uniformBinding(gpu_types::kSteerBindingWallInfo, w.info),
      gpu::uniformTexelBinding(gpu_types::kSteerBindingWallEntries, w.entryTexels),
      gpu::uniformTexelBinding(gpu_types::kSteerBindingWallStarts, w.startTexels),
  };
  gpu::dispatch(cmd, programs.steer(params.policy, cellRange(params), walls != nullptr), bindings,
                push, crowd->count);
}

std::vector<std::string> AdvanceJob::validate() const {
  std::vector<std::string> problems;
  checkCrowdAndAgents(problems, crowd, agents);
  if (!(dt >= 0.0f)) problems.push_back(concat("dt must be >= 0, got ", dt));
  if (walls && (!walls->info || !walls->segmentTexels || !walls->startTexels ||
                !walls->entryTexels || !walls->clearanceTexels))
    problems.push_back("the walls' buffers are missing (make them with uploadWalls)");
  if (walls && !(radius > 0.0f && walls->reach > radius))
    problems.push_back(concat("radius must be positive and below the walls' reach ", walls->reach,
                              " m, got ", radius));
  if (walls && agents && (!agents->steerTexels || !agents->goalTexels))
    problems.push_back("texel views of goals or steer are missing");
  return problems;
}

void AdvanceJob::record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const {
  gpu::throwIfInvalid("AdvanceJob", validate());
  if (walls) {
    recordWalled(cmd, programs);
    return;
  }
  AdvancePush push{};
  push.agentCount = crowd->count;
  push.dt = dt;
  const gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kAdvanceBindingPlacement, crowd->placement),
      gpu::storageBinding(gpu_types::kAdvanceBindingSteer, agents->steer),
      gpu::storageBinding(gpu_types::kAdvanceBindingGoals, agents->goals)};
  gpu::dispatch(cmd, programs.advance, bindings, push, crowd->count);
}

void AdvanceJob::recordWalled(VkCommandBuffer cmd, const AvoidancePrograms& programs) const {
  WallPush push{};
  push.count = crowd->count;
  push.radius = radius;
  push.maxMove = walls->reach - radius;
  push.dt = dt;
  if (push.count == 0) return;
  // `previous` is not read by the moving form; any texel view of the same format stands in.
  const gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kWallBindingPlacement, crowd->placement),
      gpu::uniformTexelBinding(gpu_types::kWallBindingPrevious, agents->steerTexels),
      gpu::uniformBinding(gpu_types::kWallBindingInfo, walls->info),
      gpu::uniformTexelBinding(gpu_types::kWallBindingEntries, walls->entryTexels),
      gpu::uniformTexelBinding(gpu_types::kWallBindingStarts, walls->startTexels),
      gpu::uniformTexelBinding(gpu_types::kWallBindingSteer, agents->steerTexels),
      gpu::uniformTexelBinding(gpu_types::kWallBindingGoals, agents->goalTexels),
      gpu::uniformTexelBinding(gpu_types::kWallBindingClearance, walls->clearanceTexels)};
  gpu::dispatch(cmd, programs.wallAdvance, bindings, push, push.count);
}

uint32_t WallConstraintJob::agents() const {
  if (count != UINT32_MAX || !crowd) return count;
  return crowd->count > firstCharacter ? crowd->count - firstCharacter : 0u;
}

std::vector<std::string> WallConstraintJob::validate() const {
  std::vector<std::string> problems;
  if (!crowd) problems.push_back("input 'crowd' buffers are missing");
  if (!previous) problems.push_back("input 'previous' (saved positions) is missing");
  if (!walls) problems.push_back("input 'walls' is missing");
  if (!crowd || !previous || !walls) return problems;
  const uint64_t end = uint64_t(firstCharacter) + agents();
  if (end > crowd->count)
    problems.push_back(concat("characters ", firstCharacter, " + ", agents(),
                              " run past the crowd's ", crowd->count));
  requireBuffer(problems, crowd->placement, VkDeviceSize(crowd->count) * 16, "placement");
  if (end > previous->capacity || !previous->texels)
    problems.push_back(concat("the saved positions hold ", previous->capacity,
                              " agents, characters up to ", end, " are constrained"));
  if (!walls->info || !walls->segmentTexels || !walls->startTexels || !walls->entryTexels ||
      !walls->clearanceTexels)
    problems.push_back("the walls' buffers are missing (make them with uploadWalls)");
  if (!(radius > 0.0f) || !std::isfinite(radius))
    problems.push_back(concat("radius must be positive, got ", radius));
  else if (!(walls->reach > radius))
    problems.push_back(concat("the walls were binned to reach ", walls->reach,
                              " m, not more than the radius ", radius, " m"));
  return problems;
}

void WallConstraintJob::record(VkCommandBuffer cmd, const AvoidancePrograms& programs) const {
  gpu::throwIfInvalid("WallConstraintJob", validate());
  WallPush push{};
  push.first = firstCharacter;
  push.count = agents();
  push.radius = radius;
  push.maxMove = walls->reach - radius;
  if (push.count == 0) return;
  const gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kWallBindingPlacement, crowd->placement),
      gpu::uniformTexelBinding(gpu_types::kWallBindingPrevious, previous->texels),
      gpu::uniformBinding(gpu_types::kWallBindingInfo, walls->info),
      gpu::uniformTexelBinding(gpu_types::kWallBindingEntries, walls->entryTexels),
      gpu::uniformTexelBinding(gpu_types::kWallBindingStarts, walls->startTexels),
      // Not read by the constraining form; texel views of the same format stand in.
      gpu::uniformTexelBinding(gpu_types::kWallBindingSteer, previous->texels),
      gpu::uniformTexelBinding(gpu_types::kWallBindingGoals, previous->texels),
      gpu::uniformTexelBinding(gpu_types::kWallBindingClearance, walls->clearanceTexels)};
  gpu::dispatch(cmd, programs.wallConstraint, bindings, push, push.count);
}

}  // namespace throng::crowd
