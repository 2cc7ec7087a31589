#pragma once
// The update-rate LOD (shaders/update_rate.h): characters far from the camera move every few
// steps, by every step since their last move, so a step of a crowd of a million characters a
// few pixels tall costs the share of it that moves. The bound: between two moves, no joint
// point of a character (joint origin or bone end) is drawn more than maxLagPixels from where
// moving it every step would draw it, at the heights its chunk had at its last move (a camera
// that comes nearer is followed within one interval, at most kUpdateMaxInterval steps). A
// character that cannot reach the view before its chunk's next move (at the longest recent
// step) counts as 0 px tall: a chunk of such characters moves every maxInterval steps, none of
// them walks into view lagging, and a camera that turns toward them is followed within that
// interval, like one that comes nearer. Root
// motion integrates exactly over the skipped steps (the root rows are lerped in the phase), so
// a character catches up to within rounding, but for a cycle end inside the skipped steps, where
// the new speed weight starts at the move instead of at the cycle end.
#include <array>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "anim/motion_texture.h"
#include "anim/root_motion.h"
#include "crowd/crowd.h"
#include "gpu/buffer.h"
#include "gpu/program.h"
#include "shaders/update_rate.h"
#include "synth/coverage.h"

namespace throng::synth {

using gpu_types::kUpdateChunkCharacters;
using gpu_types::kUpdateMaxInterval;
using gpu_types::UpdateSchedulePush;
static_assert(sizeof(UpdateSchedulePush) == 64, "UpdateSchedulePush must match the GLSL block");

// The fastest any joint point (joint origin or bone end) of `pair` moves in world space, in the
// clips' metres per second, over a cycle of each clip with its root motion.
float fastestJointSpeed(const anim::MotionPair& pair);

struct UpdateRateParams {
  float maxLagPixels = 0.0f;    // 0: every character moves every step
  float speedPerHeight = 0.0f;  // fastestJointSpeed / standing height, per second
  uint32_t maxInterval = kUpdateMaxInterval;
  bool enabled() const { return maxLagPixels > 0.0f; }
  // Pixels a joint point moves in a step of dt per pixel of projected height.
  float lagPerHeight(float dt) const { return dt * speedPerHeight; }
};
// Throws Error for a negative or non-finite lag or a standing height ≤ 0.
UpdateRateParams makeUpdateRateParams(const anim::MotionPair& pair, float standingHeight,
                                      float maxLagPixels);

uint32_t updateChunkCount(uint32_t characters);
// The stagger's block size, 2^shift chunks: as large as leaves at least 32 blocks, at most 256
// chunks (a small crowd is staggered chunk by chunk).
uint32_t updateBlockShift(uint32_t chunkCount);
// A chunk's state on both sides: its largest projected height's float bits since its last move
// and that move's step. At first, an infinite height: every chunk moves at step 0.
glm::uvec2 initialChunkState();

struct ChunkMove {
  uint32_t chunk = 0;
  uint32_t elapsed = 0;  // steps since the chunk's last move
  float seconds = 0.0f;  // their length: what the move advances by
};

// The lengths of the last kUpdateMaxInterval steps, the latest first (steps vary in length: the
// viewer's follow the wall clock, a pause's are 0).
using RecentSteps = std::array<float, kUpdateMaxInterval>;
// Records a step of dt; returns the seconds of the last 1, 2, … steps (UpdateSchedulePush::
// sinceSeconds), summed in one order for both sides.
RecentSteps advanceRecentSteps(RecentSteps& recent, float dt);
// RootMotionPush::reachPerHeight: a chunk's next move is at most maxInterval steps away, each
// taken as long as the longest of the recent steps; how far a joint point moves in that time, in
// standing heights.
float updateReachPerHeight(const UpdateRateParams& params, const RecentSteps& recent);

// CPU twin of update_schedule.comp and of the chunk heights the scheduled root motion raises.
struct UpdateScheduleCpu {
  std::vector<glm::uvec2> state;
  uint32_t step = 0;
  RecentSteps recent{};
  explicit UpdateScheduleCpu(uint32_t characters);
  // The chunks that move at this step (chunk order), their heights reset; advances the step.
  std::vector<ChunkMove> schedule(const UpdateRateParams& params, float dt);
  void raiseHeight(uint32_t chunk, float height);
};

// CPU twin of a scheduled step's root motion with its coverage (RootMotionJob with a schedule):
// the steering and new target speeds of the step for every character (root_motion_prep.comp),
// then the characters of the listed chunks moved by the seconds since their last move, their masks
// and their chunks' heights updated. `jointCount` is the pair's.
void stepScheduledCpu(const anim::MotionPair& pair, crowd::Crowd& crowd,
                      std::span<CoverageMask> masks, const CoverageCamera& camera,
                      const CoverageParts& parts, float dt, const anim::SpeedRetarget& retarget,
                      const UpdateRateParams& params, UpdateScheduleCpu& schedule);

// The GPU side: the chunks' state, this step's list and its indirect dispatch.
struct GpuUpdateRate {
  UpdateRateParams params;
  uint32_t chunkCount = 0;
  gpu::Buffer chunkState;    // uvec2 per chunk
  gpu::Buffer chunkList;     // uvec2 per chunk (ChunkMove)
  gpu::Buffer dispatchArgs;  // VkDispatchIndirectCommand
  gpu::ComputeProgram schedule;
  // The number of the next step recorded and the last steps' lengths: recording a step advances
  // them (the schedule's clock).
  mutable uint32_t step = 0;
  mutable RecentSteps recent{};
};
GpuUpdateRate makeGpuUpdateRate(const gpu::Context& context, uint32_t characters,
                                const UpdateRateParams& params);
// How many chunks the last step moved (a readback: call between frames).
uint32_t readMovedChunks(const gpu::Context& context, const GpuUpdateRate& rate);

// update_schedule.comp as a job; twin: UpdateScheduleCpu::schedule.
struct UpdateScheduleJob {
  const gpu::Buffer* chunkState = nullptr;    // input/output
  const gpu::Buffer* chunkList = nullptr;     // output
  const gpu::Buffer* dispatchArgs = nullptr;  // output: x = the list's length, y = z = 1
  uint32_t chunkCount = 0;
  uint32_t step = 0;
  RecentSteps sinceSeconds = {};  // advanceRecentSteps' sums: [0] is this step's length
  UpdateRateParams params;

  std::vector<std::string> validate() const;
  // Zeroes the count, dispatches, and orders the list before compute and indirect reads.
  void record(VkCommandBuffer cmd, const gpu::ComputeProgram& program) const;
};

}  // namespace throng::synth
