#pragma once
// A storyboard crowd in the frame (docs/design.md, "Storyboard crowds"): agents follow path vectors with
// collision avoidance on the GPU and are animated by one motion pair per clip set (walk, run,
// talk, jump). Per frame, through FrameHooks of recordCrowdFrame:
//   * before the synthesis passes: the path-vector goals (once per simulated second), the grid
//     and the avoidance job, which write each agent's heading and speed weight (w from its clip
//     pair's root speeds) for the root-motion pass to take up;
//   * with several pairs, after the first pair's synthesis: the other pairs' synthesis, then
//     their joint matrices (and LOD masks) copied into one buffer that the renderer draws;
//   * per-character tints from the storyboard groups.
//
// With several pairs each pair's CrowdSynth owns a copy of its agents' state, which is copied
// from the steering's buffers before synthesis and back after it: CrowdSynth has no way to run
// on a sub-range of shared buffers. With one pair the steering works on that pair's buffers
// directly and nothing is copied.
#include <memory>
#include <vector>

#include "crowd/avoidance_jobs.h"
#include "crowd/path_goals.h"
#include "render/crowd_frame.h"
#include "synth/crowd_synth.h"

namespace throng::render {

struct SteeredCrowdSetup {
  crowd::Crowd
      crowd;  // ordered by clip set: pair k animates agents [pairFirst[k], pairFirst[k + 1])
  crowd::AgentPaths paths;      // one per agent; agents whose paths are never active stand still
  std::vector<uint32_t> tints;  // per agent: group (tint) index
  std::vector<anim::MotionPair> pairs;  // at most crowd::kMaxClipSets (4)
  std::vector<uint32_t> pairFirst;      // pairs.size() + 1 entries, from 0 to crowd.size()
  crowd::AvoidanceParams avoidance;
};

class SteeredCrowd {
 public:
  // Throws Error for inconsistent ranges, sizes or avoidance parameters.
  SteeredCrowd(const gpu::Context& context, SteeredCrowdSetup setup,
               const synth::MotionCacheOptions& cache, const synth::LodOptions& lod);
  ~SteeredCrowd();
  SteeredCrowd(const SteeredCrowd&) = delete;
  SteeredCrowd& operator=(const SteeredCrowd&) = delete;

  // What recordCrowdFrame synthesizes itself: the first pair (every agent when there is one).
  const synth::CrowdSynth& synth() const;
  const synth::SynthPrograms& programs() const;
  // Every agent's placement and motion after the frame (the steering's buffers).
  const crowd::CrowdBuffers& crowd() const;
  uint32_t count() const;
  uint32_t jointCount() const;
  size_t pairCount() const;
  // The coverage-LOD masks of every agent as drawn (null without the LOD).
  const gpu::Buffer* drawMasks() const;
  double seconds() const { return time_; }

  // New coverage-LOD thresholds for every pair (between frames, with no frame in flight).
  void setLodThresholds(const anim::Skeleton& skeleton,
                        const synth::CoverageThresholds& thresholds);

  // Advances the simulation clock by dt and sets this frame's hooks (keeping the others, e.g.
  // cloth): call once per frame, before recordCrowdFrame.
  void addHooks(FrameHooks& hooks, float dt);

 private:
  struct Pair;
  void recordSteering(VkCommandBuffer cmd, const crowd::SteerFrame& frame,
                      int64_t goalSecond) const;
  void recordOtherPairs(VkCommandBuffer cmd, const synth::CoverageCamera& lodCamera,
                        DrawParams& params, float dt) const;

  const gpu::Context& context_;
  crowd::AvoidanceParams avoidance_;
  std::vector<std::unique_ptr<anim::MotionPair>> motionPairs_;
  std::vector<std::unique_ptr<synth::SynthPrograms>> programs_;
  std::vector<Pair> pairs_;
  crowd::AvoidancePrograms steerPrograms_;
  crowd::CrowdBuffers shared_;  // several pairs: every agent's state (one pair: its own)
  crowd::SteerBuffers agents_;
  crowd::GridBuffers grid_;
  crowd::PathBuffers paths_;
  gpu::Buffer tints_;
  gpu::Buffer joints_, masks_;  // several pairs: what the renderer draws
  std::vector<crowd::ClipSpeeds> speeds_;
  double time_ = 0.0;
  uint32_t step_ = 0;
  int64_t goalSecond_ = -1;
};

}  // namespace throng::render
