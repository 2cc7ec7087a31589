#pragma once
// A scene: ONE crowd (every character's state in one set of GPU buffers, structure of arrays)
// split into groups, each a contiguous range of characters with its clip set (motion pair) and
// tint, plus the behaviour that moves them: plain heading and speed (with optional speed
// changes), or steering along path vectors with avoidance (storyboards, the circle's lanes).
// Random, circle and storyboard scenes are all built as a Scene; the frame (scene/frame.h)
// records its stages from it. A new behaviour goes here (a SceneSetup field and a stage in the
// frame); a new output reads the scene's buffers after a frame.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "crowd/crowd_steering.h"
#include "crowd/obstacles.h"
#include "crowd/path_vectors.h"
#include "synth/crowd_synth.h"

namespace throng::scene {

// How every agent of a steered scene is led: path vectors (storyboards, the circle's lanes) or
// goals with navigation (Menge scenarios), with avoidance of each other and of the walls.
struct SteeringSetup {
  crowd::AgentPaths paths;  // one per agent; agents whose paths are never active stand still
  crowd::AvoidanceParams avoidance;
  std::optional<crowd::GoalScene> goals;  // instead of paths (then `paths` stays empty)
};

// What a scene is made of, on the CPU.
struct SceneSetup {
  crowd::Crowd crowd;                   // every character, ordered by group
  std::vector<anim::MotionPair> pairs;  // group k's clip set (at most kMaxClipSets)
  std::vector<uint32_t> groupFirst;     // pairs.size() + 1 entries, from 0 to crowd.size()
  std::vector<uint32_t> tints;          // per character: its tint index (empty: no tints)
  std::vector<uint32_t> labels;         // per character: its group label in exports (or empty)
  std::optional<SteeringSetup> steering;
  // Static walls (empty: none; steered scenes only): the steering avoids them and a constraint
  // after root motion keeps every character off them (crowd::WallConstraintJob).
  crowd::Obstacles walls;
  synth::SpeedSchedule speeds;  // speed changes of unsteered scenes (period 0: none)
};

// This frame's step of the scene's behaviour (Scene::advance).
struct SceneStep {
  float dt = 0.0f;
  anim::SpeedRetarget retarget;              // unsteered scenes' speed changes
  std::optional<crowd::SteerStep> steering;  // steered scenes
};

class Scene {
 public:
  // Throws Error for inconsistent groups, sizes or avoidance parameters, gpu::LimitError past a
  // device limit.
  Scene(const gpu::Context& context, SceneSetup setup, const synth::MotionCacheOptions& cache,
        const synth::LodOptions& lod);
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  const synth::CrowdSynth& synth() const { return synth_; }
  // The compiled passes of each group (groups with the same clip set share them).
  std::span<const synth::SynthPrograms* const> programs() const { return groupPrograms_; }
  const crowd::CrowdBuffers& crowd() const { return synth_.crowd; }
  uint32_t count() const { return synth_.crowd.count; }
  uint32_t jointCount() const { return synth_.jointCount(); }
  size_t groupCount() const { return synth_.groups.size(); }
  const anim::MotionPair& pair(size_t group) const { return *pairs_.at(group); }
  // Per character tint index (null: the scene has none).
  const gpu::Buffer* tints() const { return tints_ ? &tints_ : nullptr; }
  // Per character: the group label exports write (storyboard groups; empty: none).
  const std::vector<uint32_t>& labels() const { return labels_; }
  bool steered() const { return steering_ != nullptr; }
  synth::SpeedSchedule& speeds() { return speeds_; }
  double seconds() const { return time_; }
  // Per character: whether it is on the scene at `seconds` (steered characters follow their
  // paths' first and last seconds; everyone else always is).
  std::vector<uint8_t> activeAt(double seconds) const;

  // New coverage-LOD thresholds for every group (between frames, with no frame in flight).
  void setLodThresholds(const anim::Skeleton& skeleton,
                        const synth::CoverageThresholds& thresholds);

  // Advances the scene's clock by dt: what this frame's stages do. Call once per frame.
  SceneStep advance(float dt);
  // The steer stage of a frame (nothing for unsteered scenes).
  void recordSteering(VkCommandBuffer cmd, const SceneStep& step) const;
  // Walls: before root motion the positions are saved; after it, the wall constraint.
  bool hasWalls() const { return steering_ && steering_->walls(); }
  void recordSavePositions(VkCommandBuffer cmd) const;
  void recordWallConstraint(VkCommandBuffer cmd) const;
  const crowd::WallBuffers* walls() const { return steering_ ? steering_->walls() : nullptr; }

  // Goals: between frames, with none in flight (waits for the device), the state machines run
  // on read-back positions and changed goals are planned. Call every few frames (arrivals and
  // timers are seen that much later). Nothing for scenes without goals.
  bool hasGoals() const { return steering_ && steering_->goals(); }
  void updateGoals(const gpu::Context& context);
  uint32_t agentsAtGoal() const;  // in a final state, reached (0 without goals)
  bool goalsDone() const;         // every agent with goals is done

 private:
  void makeSteering(const gpu::Context& context, SceneSetup& setup);

  std::vector<std::unique_ptr<anim::MotionPair>> pairs_;
  std::vector<std::unique_ptr<synth::SynthPrograms>> programs_;
  std::vector<const synth::SynthPrograms*> groupPrograms_;
  synth::CrowdSynth synth_;
  std::unique_ptr<crowd::CrowdSteering> steering_;
  std::unique_ptr<crowd::SavedPositions> saved_;  // walls: placement before root motion
  crowd::AgentPaths paths_;
  std::vector<uint32_t> labels_;
  gpu::Buffer tints_;
  synth::SpeedSchedule speeds_;
  double time_ = 0.0;
};

}  // namespace throng::scene
