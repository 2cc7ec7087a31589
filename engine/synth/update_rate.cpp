#include "synth/update_rate.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "anim/reference_synth.h"
#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/job_check.h"
#include "shaders/synth_bindings.h"
#include "synth/gpu_types.h"

namespace throng::synth {

namespace {

// Bone starts and ends (y = 0 and 1 in a joint's draw space) of a pose.
void jointPoints(const anim::MotionPair& pair, const glm::vec4& placement, const glm::vec4& motion,
                 std::vector<glm::vec4>& pose, std::vector<glm::vec3>& points) {
  anim::poseCharacter(pair, placement, motion, pose);
  points.clear();
  for (size_t j = 0; j < pose.size(); ++j) {
    const int parent = pair.parents[j];
    const glm::vec4 from = parent < 0 ? pose[j] : pose[size_t(parent)];
    points.push_back(gpu_types::bonePoint(from, pose[j], parent < 0, 0.0f));
    points.push_back(gpu_types::bonePoint(from, pose[j], parent < 0, 1.0f));
  }
}

// The fastest joint point of one clip (speed weight w) over a cycle, in small steps.
float fastestAtWeight(const anim::MotionPair& pair, float w) {
  const float duration = w < 0.5f ? pair.slow.duration() : pair.fast.duration();
  const int frames = w < 0.5f ? pair.slow.frameCount : pair.fast.frameCount;
  const int steps = 4 * std::max(frames, 1);
  const float dt = duration / float(steps);
  glm::vec4 placement(0.0f), motion = gpu_types::makeMotion(0.0f, w, w, 1.0f);
  std::vector<glm::vec4> pose(size_t(pair.jointCount()));
  std::vector<glm::vec3> before, after;
  jointPoints(pair, placement, motion, pose, before);
  float fastest = 0.0f;
  for (int s = 0; s < steps; ++s) {
    anim::stepCharacter(pair, placement, motion, dt, anim::Steering::KeepHeading);
    jointPoints(pair, placement, motion, pose, after);
    for (size_t p = 0; p < after.size(); ++p)
      fastest = std::max(fastest, glm::length(after[p] - before[p]) / dt);
    std::swap(before, after);
  }
  return fastest;
}

}  // namespace

float fastestJointSpeed(const anim::MotionPair& pair) {
  return std::max(fastestAtWeight(pair, 0.0f), fastestAtWeight(pair, 1.0f));
}

UpdateRateParams makeUpdateRateParams(const anim::MotionPair& pair, float standingHeight,
                                      float maxLagPixels) {
  THRONG_CHECK(std::isfinite(maxLagPixels) && maxLagPixels >= 0.0f,
               "update-rate LOD: the lag must be a number of pixels >= 0, got ", maxLagPixels);
  THRONG_CHECK(standingHeight > 0.0f, "update-rate LOD: the standing height must be > 0, got ",
               standingHeight);
  UpdateRateParams params;
  params.maxLagPixels = maxLagPixels;
  params.speedPerHeight = fastestJointSpeed(pair) / standingHeight;
  return params;
}

uint32_t updateChunkCount(uint32_t characters) {
  return (characters + kUpdateChunkCharacters - 1) / kUpdateChunkCharacters;
}

uint32_t updateBlockShift(uint32_t chunkCount) {
  uint32_t shift = 0;
  while (shift < 8 && (chunkCount >> (shift + 1)) >= 32) ++shift;
  return shift;
}

RecentSteps advanceRecentSteps(RecentSteps& recent, float dt) {
  for (size_t k = recent.size() - 1; k > 0; --k) recent[k] = recent[k - 1];
  recent[0] = dt;
  RecentSteps since{};
  float sum = 0.0f;
  for (size_t k = 0; k < recent.size(); ++k) since[k] = sum += recent[k];
  return since;
}

float updateReachPerHeight(const UpdateRateParams& params, const RecentSteps& recent) {
  const float longest = *std::max_element(recent.begin(), recent.end());
  return float(params.maxInterval) * params.lagPerHeight(longest);
}

glm::uvec2 initialChunkState() {
  return {std::bit_cast<uint32_t>(std::numeric_limits<float>::infinity()), ~0u};
}

UpdateScheduleCpu::UpdateScheduleCpu(uint32_t characters)
    : state(updateChunkCount(characters), initialChunkState()) {}

std::vector<ChunkMove> UpdateScheduleCpu::schedule(const UpdateRateParams& params, float dt) {
  std::vector<ChunkMove> moves;
  const uint32_t blockShift = updateBlockShift(uint32_t(state.size()));
  const RecentSteps since = advanceRecentSteps(recent, dt);
  for (uint32_t c = 0; c < state.size(); ++c) {
    const uint32_t interval =
        gpu_types::updateInterval(std::bit_cast<float>(state[c].x), params.lagPerHeight(dt),
                                  params.maxLagPixels, params.maxInterval);
    if (!gpu_types::updateDue(step, state[c].y, c, interval, blockShift)) continue;
    const uint32_t elapsed = std::min(step - state[c].y, kUpdateMaxInterval);
    moves.push_back({c, elapsed, since[elapsed - 1]});
    state[c] = {0u, step};
  }
  ++step;
  return moves;
}

void UpdateScheduleCpu::raiseHeight(uint32_t chunk, float height) {
  state[chunk].x = std::max(state[chunk].x, std::bit_cast<uint32_t>(height));
}

void stepScheduledCpu(const anim::MotionPair& pair, crowd::Crowd& crowd,
                      std::span<CoverageMask> masks, const CoverageCamera& camera,
                      const CoverageParts& parts, float dt, const anim::SpeedRetarget& retarget,
                      const UpdateRateParams& params, UpdateScheduleCpu& schedule) {
  const uint32_t n = uint32_t(crowd.size());
  THRONG_CHECK(masks.size() >= n && schedule.state.size() == updateChunkCount(n),
               "scheduled step: ", masks.size(), " masks and ", schedule.state.size(),
               " chunks for ", n, " characters");
  // root_motion_prep.comp runs over every character, moving or not.
  for (uint32_t i = 0; i < n; ++i) {
    glm::vec4& p = crowd.placement[i];
    if (crowd.steering == anim::Steering::Circle) p.w = anim::circleHeading(glm::vec2(p.x, p.z));
    anim::applyRetarget(i, retarget, crowd.motion[i]);
  }
  const CoveragePush push = makeCoveragePush(camera, uint32_t(pair.jointCount()), 0, n, 0u);
  const std::vector<ChunkMove> moves = schedule.schedule(params, dt);
  const float reachPerHeight = updateReachPerHeight(params, schedule.recent);
  for (const ChunkMove& move : moves) {
    const uint32_t end = std::min(n, (move.chunk + 1) * kUpdateChunkCharacters);
    for (uint32_t i = move.chunk * kUpdateChunkCharacters; i < end; ++i) {
      glm::vec4& p = crowd.placement[i];
      glm::vec4& m = crowd.motion[i];
      anim::stepCharacter(pair, p, m, move.seconds, anim::Steering::KeepHeading);
      masks[i] = coverageCharacter(push, parts, p, m, nullptr, masks[i], nullptr);
      // A character that cannot reach the view before its chunk's next move counts as 0 px.
      const bool withinReach = bodyWithinReach(push, parts, p, m, reachPerHeight);
      schedule.raiseHeight(move.chunk,
                           withinReach ? characterHeightPixels(push, parts, p, m) : 0.0f);
    }
  }
}

GpuUpdateRate makeGpuUpdateRate(const gpu::Context& context, uint32_t characters,
                                const UpdateRateParams& params) {
  GpuUpdateRate rate{params, updateChunkCount(characters)};
  const std::vector<glm::uvec2> state(rate.chunkCount, initialChunkState());
  rate.chunkState = gpu::makeStorageBuffer<glm::uvec2>(context, state);
  rate.chunkList = gpu::Buffer(context, std::max<VkDeviceSize>(rate.chunkCount, 2) * 8,
                               gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  const uint32_t args[] = {0u, 1u, 1u};
  rate.dispatchArgs = gpu::makeStorageBuffer<uint32_t>(context, args, gpu::MemoryUse::DeviceLocal,
                                                       VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
  rate.schedule = gpu::ComputeProgram(context, "update_schedule.comp");
  return rate;
}

uint32_t readMovedChunks(const gpu::Context& context, const GpuUpdateRate& rate) {
  return gpu::readback<uint32_t>(context, rate.dispatchArgs, 1)[0];
}

std::vector<std::string> UpdateScheduleJob::validate() const {
  std::vector<std::string> problems;
  if (!chunkState || !*chunkState) problems.push_back("input/output 'chunkState' is missing");
  if (!chunkList || !*chunkList) problems.push_back("output 'chunkList' is missing");
  if (!dispatchArgs || !*dispatchArgs) problems.push_back("output 'dispatchArgs' is missing");
  if (chunkCount == 0) problems.push_back("chunkCount must be > 0");
  if (chunkState && *chunkState && chunkState->size() < VkDeviceSize(chunkCount) * 8)
    problems.push_back(concat("buffer 'chunkState' holds ", chunkState->size(), " bytes, ",
                              VkDeviceSize(chunkCount) * 8, " needed"));
  if (chunkList && *chunkList && chunkList->size() < VkDeviceSize(chunkCount) * 8)
    problems.push_back(concat("buffer 'chunkList' holds ", chunkList->size(), " bytes, ",
                              VkDeviceSize(chunkCount) * 8, " needed"));
  if (!params.enabled()) problems.push_back("the lag must be > 0 pixels (0: no schedule)");
  if (params.maxInterval < 1 || params.maxInterval > kUpdateMaxInterval)
    problems.push_back(concat("maxInterval must be 1 to ", kUpdateMaxInterval, " steps, got ",
                              params.maxInterval));
  for (float seconds : sinceSeconds)
    if (!(seconds >= 0.0f) || !std::isfinite(seconds))
      problems.push_back(concat("sinceSeconds must be seconds >= 0, got ", seconds));
  return problems;
}

void UpdateScheduleJob::record(VkCommandBuffer cmd, const gpu::ComputeProgram& program) const {
  gpu::throwIfInvalid("UpdateScheduleJob", validate());
  // A step recorded earlier in the same command buffer may still read the arguments and the list.
  gpu::memoryBarrier(cmd,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  vkCmdFillBuffer(cmd, dispatchArgs->get(), 0, 4, 0u);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  UpdateSchedulePush push{};
  push.chunkCount = chunkCount;
  push.step = step;
  push.lagPerHeight = params.lagPerHeight(sinceSeconds[0]);
  push.maxLag = params.maxLagPixels;
  push.maxInterval = params.maxInterval;
  push.blockShift = updateBlockShift(chunkCount);
  std::copy(sinceSeconds.begin(), sinceSeconds.end(), push.sinceSeconds);
  const gpu::Binding bindings[] = {
      gpu::storageBinding(gpu_types::kUpdateScheduleBindingChunkState, *chunkState),
      gpu::storageBinding(gpu_types::kUpdateScheduleBindingChunkList, *chunkList),
      gpu::storageBinding(gpu_types::kUpdateScheduleBindingArgs, *dispatchArgs)};
  gpu::dispatch(cmd, program, bindings, push, chunkCount);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT);
}

}  // namespace throng::synth
