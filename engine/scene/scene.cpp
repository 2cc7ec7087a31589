#include "scene/scene.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "crowd/avoidance_types.h"

namespace throng::scene {

namespace {

void checkSetup(const SceneSetup& s) {
  const size_t n = s.crowd.size();
  if (n == 0) fail("a scene needs at least one character");
  if (s.pairs.empty() || s.pairs.size() > gpu_types::kMaxClipSets)
    fail("a scene needs 1 to ", gpu_types::kMaxClipSets, " clip sets, got ", s.pairs.size());
  if (!s.tints.empty() && s.tints.size() != n)
    fail("scene: ", n, " characters but ", s.tints.size(), " tints");
  if (!s.labels.empty() && s.labels.size() != n)
    fail("scene: ", n, " characters but ", s.labels.size(), " labels");
  if (s.steering && !s.steering->goals && s.steering->paths.size() != n)
    fail("scene: ", n, " characters but ", s.steering->paths.size(), " paths");
  if (s.steering && s.steering->goals && s.steering->paths.size() > 0)
    fail("scene: agents follow goals or path vectors, not both");
  if (!s.walls.empty() && !s.steering) fail("scene: walls need a steered scene");
}

std::vector<crowd::ClipSpeeds> clipSpeeds(
    const std::vector<std::unique_ptr<anim::MotionPair>>& pairs,
    const std::vector<uint32_t>& groupFirst) {
  std::vector<crowd::ClipSpeeds> speeds;
  for (size_t k = 0; k < pairs.size(); ++k)
    speeds.push_back({anim::clipRootSpeed(pairs[k]->slow), anim::clipRootSpeed(pairs[k]->fast),
                      groupFirst[k + 1]});
  return speeds;
}

}  // namespace

Scene::Scene(const gpu::Context& context, SceneSetup setup, const synth::MotionCacheOptions& cache,
             const synth::LodOptions& lod)
    : speeds_(setup.speeds) {
  checkSetup(setup);
  // A steered scene steers every character from every other's place, each step.
  if (setup.steering && lod.updateLagPixels > 0.0f)
    fail(
        "the update-rate LOD needs an unsteered crowd: a steered scene moves every character "
        "every step");
  std::vector<const anim::MotionPair*> pairs;
  for (anim::MotionPair& p : setup.pairs) {
    pairs_.push_back(std::make_unique<anim::MotionPair>(std::move(p)));
    pairs.push_back(pairs_.back().get());
  }
  synth_ = synth::makeCrowdSynth(context, pairs, setup.groupFirst, setup.crowd, cache, lod);
  // Groups whose pairs bake the same values into the passes (skeleton, bones, where the texels
  // are read) share them.
  for (size_t k = 0; k < pairs_.size(); ++k) {
    const synth::SynthPrograms* programs = nullptr;
    for (const auto& built : programs_)
      if (!programs && built->fits(context, *pairs_[k])) programs = built.get();
    if (!programs) {
      programs_.push_back(std::make_unique<synth::SynthPrograms>(context, *pairs_[k]));
      programs = programs_.back().get();
    }
    groupPrograms_.push_back(programs);
  }
  if (setup.steering) makeSteering(context, setup);
  if (!setup.tints.empty()) tints_ = gpu::makeStorageBuffer<uint32_t>(context, setup.tints);
  labels_ = std::move(setup.labels);
}

Scene::~Scene() = default;

void Scene::makeSteering(const gpu::Context& context, SceneSetup& setup) {
  SteeringSetup& s = *setup.steering;
  std::vector<crowd::ClipSpeeds> speeds = clipSpeeds(pairs_, setup.groupFirst);
  if (s.goals) {
    steering_ =
        std::make_unique<crowd::CrowdSteering>(context, count(), s.avoidance, std::move(speeds));
    steering_->setGoals(context, std::move(*s.goals), setup.crowd.placement);
  } else {
    paths_ = std::move(s.paths);
    steering_ =
        std::make_unique<crowd::CrowdSteering>(context, paths_, s.avoidance, std::move(speeds));
  }
  if (!setup.walls.empty()) {
    steering_->setWalls(context, setup.walls);
    saved_ = std::make_unique<crowd::SavedPositions>(crowd::makeSavedPositions(context, count()));
  }
}

void Scene::recordSavePositions(VkCommandBuffer cmd) const {
  if (saved_) crowd::recordSavePositions(cmd, synth_.crowd, *saved_, 0, count());
}

void Scene::recordWallConstraint(VkCommandBuffer cmd) const {
  if (!saved_ || !steering_->walls()) return;
  crowd::WallConstraintJob job{&synth_.crowd, saved_.get(), steering_->walls(),
                               steering_->avoidance().radius};
  job.record(cmd, steering_->programs());
}

void Scene::updateGoals(const gpu::Context& context) {
  if (hasGoals()) steering_->updateGoals(context, synth_.crowd);
}

uint32_t Scene::agentsAtGoal() const {
  return hasGoals() ? steering_->goals()->agentsAtGoal() : 0;
}

bool Scene::goalsDone() const {
  return hasGoals() && steering_->goals()->allDone();
}

std::vector<uint8_t> Scene::activeAt(double seconds) const {
  std::vector<uint8_t> active(count(), 1);
  if (paths_.size() != active.size()) return active;
  const uint32_t second = uint32_t(std::clamp(std::floor(seconds), 0.0, 4.0e9));
  for (size_t i = 0; i < active.size(); ++i) active[i] = paths_.active(i, second) ? 1 : 0;
  return active;
}

void Scene::setLodThresholds(const anim::Skeleton& skeleton,
                             const synth::CoverageThresholds& thresholds) {
  synth::setLodThresholds(synth_, skeleton, thresholds);
}

SceneStep Scene::advance(float dt) {
  SceneStep step;
  step.dt = dt;
  if (steering_)
    step.steering = steering_->advance(dt);
  else
    step.retarget = speeds_.advance(dt);
  time_ += dt;
  return step;
}

void Scene::recordSteering(VkCommandBuffer cmd, const SceneStep& step) const {
  if (steering_ && step.steering) steering_->record(cmd, synth_.crowd, *step.steering);
}

}  // namespace throng::scene
