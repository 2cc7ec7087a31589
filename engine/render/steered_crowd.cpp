#include "render/steered_crowd.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "crowd/avoidance_types.h"
#include "crowd/path_vectors.h"
#include "gpu/commands.h"

namespace throng::render {

struct SteeredCrowd::Pair {
  const synth::SynthPrograms* programs = nullptr;
  synth::CrowdSynth synth;
  uint32_t first = 0, count = 0;
};

namespace {

void checkSetup(const SteeredCrowdSetup& s) {
  const size_t n = s.crowd.size();
  if (n == 0) fail("a steered crowd needs at least one agent");
  if (s.pairs.empty() || s.pairs.size() > gpu_types::kMaxClipSets)
    fail("a steered crowd needs 1 to ", gpu_types::kMaxClipSets, " motion pairs, got ",
         s.pairs.size());
  if (s.pairFirst.size() != s.pairs.size() + 1 || s.pairFirst.front() != 0 ||
      s.pairFirst.back() != n)
    fail("steered crowd: pair ranges must run from 0 to the ", n, " agents, one range per pair");
  for (size_t k = 0; k + 1 < s.pairFirst.size(); ++k)
    if (s.pairFirst[k + 1] <= s.pairFirst[k])
      fail("steered crowd: motion pair ", k, " has no agent");
  if (s.paths.size() != n || s.tints.size() != n)
    fail("steered crowd: ", n, " agents but ", s.paths.size(), " paths and ", s.tints.size(),
         " tints");
  const std::vector<std::string> problems = crowd::validateParams(s.avoidance);
  if (!problems.empty()) fail("avoidance parameters: ", problems.front());
  for (const anim::MotionPair& p : s.pairs)
    if (p.jointCount() != s.pairs.front().jointCount())
      fail("steered crowd: every motion pair needs the same skeleton (", p.jointCount(),
           " joints vs ", s.pairs.front().jointCount(), ")");
}

crowd::Crowd slice(const crowd::Crowd& all, uint32_t first, uint32_t count) {
  crowd::Crowd part;
  part.placement.assign(all.placement.begin() + first, all.placement.begin() + first + count);
  part.motion.assign(all.motion.begin() + first, all.motion.begin() + first + count);
  part.clipSet.assign(all.clipSet.begin() + first, all.clipSet.begin() + first + count);
  return part;
}

bool sameSkeleton(const anim::MotionPair& a, const anim::MotionPair& b) {
  return a.parents == b.parents;
}

VkDeviceSize perCharacterBytes(const gpu::Buffer& buffer, uint32_t count) {
  return buffer.size() / count;
}

void copyRange(VkCommandBuffer cmd, const gpu::Buffer& from, VkDeviceSize fromOffset,
               const gpu::Buffer& to, VkDeviceSize toOffset, VkDeviceSize bytes) {
  VkBufferCopy region{fromOffset, toOffset, bytes};
  vkCmdCopyBuffer(cmd, from.get(), to.get(), 1, &region);
}

}  // namespace

SteeredCrowd::SteeredCrowd(const gpu::Context& context, SteeredCrowdSetup setup,
                           const synth::MotionCacheOptions& cache, const synth::LodOptions& lod)
    : context_(context), avoidance_(setup.avoidance), steerPrograms_(context) {
  checkSetup(setup);
  const uint32_t n = uint32_t(setup.crowd.size());
  // Motion pairs with the same skeleton share their compiled passes (the skeleton is baked in).
  for (anim::MotionPair& p : setup.pairs)
    motionPairs_.push_back(std::make_unique<anim::MotionPair>(std::move(p)));
  for (size_t k = 0; k < motionPairs_.size(); ++k) {
    const anim::MotionPair& pair = *motionPairs_[k];
    const uint32_t first = setup.pairFirst[k], count = setup.pairFirst[k + 1] - first;
    const synth::SynthPrograms* programs = nullptr;
    for (size_t j = 0; j < k && !programs; ++j)
      if (sameSkeleton(*motionPairs_[j], pair)) programs = pairs_[j].programs;
    if (!programs) {
      programs_.push_back(std::make_unique<synth::SynthPrograms>(context, pair));
      programs = programs_.back().get();
    }
    crowd::Crowd part = motionPairs_.size() == 1 ? setup.crowd : slice(setup.crowd, first, count);
    pairs_.push_back(
        {programs, synth::makeCrowdSynth(context, pair, part, cache, lod), first, count});
    const float slow = crowd::clipRootSpeed(pair.slow), fast = crowd::clipRootSpeed(pair.fast);
    speeds_.push_back({slow, fast, first + count});
  }
  if (pairs_.size() > 1) {
    shared_ = crowd::uploadCrowd(context, setup.crowd);
    const synth::CrowdSynth& s = pairs_.front().synth;
    joints_ = gpu::Buffer(context, perCharacterBytes(s.joints, s.crowd.count) * n,
                          gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
    if (s.lod)
      masks_ = gpu::Buffer(context, perCharacterBytes(s.masks, s.crowd.count) * n,
                           gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  }
  std::vector<glm::vec4> goals(n, glm::vec4(0.0f)), steer(n, glm::vec4(0.0f));
  agents_ = crowd::uploadSteer(context, goals, steer);
  grid_ = crowd::makeGridBuffers(context, n, avoidance_.cellSize);
  paths_ = crowd::uploadPaths(context, setup.paths);
  tints_ = gpu::makeStorageBuffer<uint32_t>(context, setup.tints);
}

SteeredCrowd::~SteeredCrowd() = default;

const synth::CrowdSynth& SteeredCrowd::synth() const {
  return pairs_.front().synth;
}
const synth::SynthPrograms& SteeredCrowd::programs() const {
  return *pairs_.front().programs;
}
const crowd::CrowdBuffers& SteeredCrowd::crowd() const {
  return pairs_.size() == 1 ? pairs_.front().synth.crowd : shared_;
}
uint32_t SteeredCrowd::count() const {
  return crowd().count;
}
uint32_t SteeredCrowd::jointCount() const {
  return pairs_.front().synth.jointCount();
}
size_t SteeredCrowd::pairCount() const {
  return pairs_.size();
}
const gpu::Buffer* SteeredCrowd::drawMasks() const {
  if (!pairs_.front().synth.lod) return nullptr;
  return pairs_.size() == 1 ? &pairs_.front().synth.masks : &masks_;
}

void SteeredCrowd::setLodThresholds(const anim::Skeleton& skeleton,
                                    const synth::CoverageThresholds& thresholds) {
  for (Pair& p : pairs_)
    if (p.synth.lod) synth::setLodThresholds(p.synth, skeleton, thresholds);
}

void SteeredCrowd::addHooks(FrameHooks& hooks, float dt) {
  // The waypoint of second s is due at its end: steps inside it head for it with the time left.
  const int64_t second = int64_t(std::floor(time_));
  crowd::SteerFrame frame;
  frame.dt = dt;
  frame.secondsLeft = std::max(float(double(second + 1) - time_), 1e-3f);
  frame.step = step_++;
  frame.sets = speeds_;
  const int64_t goals = second != goalSecond_ ? second : -1;
  goalSecond_ = second;
  time_ += dt;
  hooks.beforeSynthesis = [this, frame, goals](VkCommandBuffer cmd) {
    recordSteering(cmd, frame, goals);
  };
  hooks.moreSynthesis = [this, dt](VkCommandBuffer cmd, const synth::CoverageCamera& camera,
                                   DrawParams& params) {
    recordOtherPairs(cmd, camera, params, dt);
  };
}

void SteeredCrowd::recordSteering(VkCommandBuffer cmd, const crowd::SteerFrame& frame,
                                  int64_t goalSecond) const {
  const crowd::CrowdBuffers& all = crowd();
  // The previous frame's synthesis and copies wrote the state the grid reads.
  gpu::computeToComputeBarrier(cmd);
  if (goalSecond >= 0) {
    crowd::GoalJob{&paths_, &agents_, uint32_t(goalSecond)}.record(cmd, steerPrograms_);
    gpu::computeToComputeBarrier(cmd);
  }
  crowd::GridJob{&all, &agents_, &grid_}.record(cmd, steerPrograms_);
  gpu::computeToComputeBarrier(cmd);
  crowd::AvoidanceJob{&all, &agents_, &grid_, avoidance_, frame}.record(cmd, steerPrograms_);
  gpu::computeToComputeBarrier(cmd);
  if (pairs_.size() == 1) return;
  for (const Pair& p : pairs_) {
    copyRange(cmd, shared_.placement, VkDeviceSize(p.first) * 16, p.synth.crowd.placement, 0,
              VkDeviceSize(p.count) * 16);
    copyRange(cmd, shared_.motion, VkDeviceSize(p.first) * 16, p.synth.crowd.motion, 0,
              VkDeviceSize(p.count) * 16);
  }
  gpu::computeToComputeBarrier(cmd);
}

void SteeredCrowd::recordOtherPairs(VkCommandBuffer cmd, const synth::CoverageCamera& lodCamera,
                                    DrawParams& params, float dt) const {
  params.groups = &tints_;
  if (pairs_.size() == 1) return;
  const VkDeviceSize maxBinding = context_.info().maxStorageBufferRange;
  for (size_t k = 1; k < pairs_.size(); ++k)
    synth::recordSynthesis(cmd, *pairs_[k].programs, pairs_[k].synth, dt, maxBinding, {},
                           &lodCamera);
  gpu::computeToComputeBarrier(cmd);
  // The renderer reads one joints buffer: cached characters' joints are written out first.
  for (const Pair& p : pairs_)
    synth::recordMaterializeCachedPoses(cmd, *p.programs, p.synth, maxBinding);
  gpu::computeToComputeBarrier(cmd);
  for (const Pair& p : pairs_) {
    const synth::CrowdSynth& s = p.synth;
    const VkDeviceSize joints = perCharacterBytes(s.joints, s.crowd.count);
    copyRange(cmd, s.joints, 0, joints_, VkDeviceSize(p.first) * joints,
              VkDeviceSize(p.count) * joints);
    if (masks_) {
      const VkDeviceSize mask = perCharacterBytes(s.masks, s.crowd.count);
      copyRange(cmd, s.masks, 0, masks_, VkDeviceSize(p.first) * mask,
                VkDeviceSize(p.count) * mask);
    }
    // Root motion moved the pair's agents: the next frame's steering starts from there.
    copyRange(cmd, s.crowd.placement, 0, shared_.placement, VkDeviceSize(p.first) * 16,
              VkDeviceSize(p.count) * 16);
    copyRange(cmd, s.crowd.motion, 0, shared_.motion, VkDeviceSize(p.first) * 16,
              VkDeviceSize(p.count) * 16);
  }
  params.characterCount = count();
  params.joints = &joints_;
  params.masks = masks_ ? &masks_ : nullptr;
  params.cachedPoses = {};
}

}  // namespace throng::render
