#include "scene/corridor_scene.h"

#include <cmath>

#include "anim/default_clips.h"
#include "core/error.h"
#include "crowd/goals.h"
#include "storyboard/codec.h"
#include "storyboard/example.h"
#include "storyboard/legend.h"
#include "storyboard/quilt.h"
#include "storyboard/storyboard_placement.h"

namespace throng::scene {
namespace sb = throng::storyboard;

namespace {

constexpr int kMaxPixels = 16 << 20;

sb::Storyboard quiltCorridor(const CorridorDescription& d, int width, int height) {
  sb::ExampleOptions example;
  example.seed = d.seed;
  example.density = d.density;
  const sb::Legend legend;
  const ImageRgba8 sample = sb::encodeStoryboard(example.width, example.height,
                                                 sb::generateExampleGlyphs(example), legend);
  sb::QuiltOptions quilt;
  quilt.width = width;
  quilt.height = height;
  quilt.seed = d.seed;
  return sb::decodeStoryboard(sb::quiltStoryboard(sample, legend, quilt).image, legend);
}

// Walkers head for the open end their glyph faces (its heading's x component); the clip sets
// that do not travel (talkers) stand and have no goal.
crowd::GoalScene corridorGoals(const CorridorDescription& d, const crowd::Crowd& crowd,
                               const std::vector<float>& rootSpeed,
                               const std::vector<uint32_t>& setOfAgent) {
  crowd::GoalScene goals;
  const float x = 0.5f * d.length, z = 0.5f * d.width;
  goals.goalSets.push_back({{crowd::boxGoal({x, -z + 0.5f}, {x + 4.0f, z - 0.5f})}});
  goals.goalSets.push_back({{crowd::boxGoal({-x - 4.0f, -z + 0.5f}, {-x, z - 0.5f})}});
  for (uint32_t k = 0; k < 2; ++k) {
    crowd::GoalBehavior behavior;
    crowd::GoalState walk;
    walk.choice.kind = crowd::GoalChoice::Kind::Explicit;
    walk.choice.goalSet = k;
    walk.choice.sampleInside = true;
    walk.onArrival = crowd::GoalState::Arrival::Stop;
    walk.reach = 0.5f;
    behavior.states.push_back(walk);
    behavior.maxSpeed = 2.5f;
    goals.groups.push_back(behavior);
  }
  for (size_t i = 0; i < crowd.size(); ++i) {
    const bool walks = rootSpeed[setOfAgent[i]] > 0.0f;
    goals.agentGroup.push_back(!walks ? crowd::kNoState
                                      : (std::sin(crowd.placement[i].w) >= 0.0f ? 0u : 1u));
  }
  goals.seed = uint32_t(d.seed);
  return goals;
}

}  // namespace

SceneSetup corridorScene(const CorridorDescription& d) {
  if (!(d.cell > 0.0f) || !(d.length > 0.0f) || !(d.width > 1.0f))
    fail("corridor: length and cell must be > 0 metres and width > 1 m");
  // Agents start half a metre or more from the walls.
  const double w = std::ceil(double(d.length) / d.cell),
               h = std::ceil(double(d.width - 1.0f) / d.cell);
  if (w < 20 || h < 20 || w * h > kMaxPixels)
    fail("corridor: ", d.length, " × ", d.width, " m at ", d.cell, " m per pixel is ", w, " × ", h,
         " pixels; expected 20 × 20 to ", kMaxPixels, " pixels");
  const sb::Storyboard board = quiltCorridor(d, int(w), int(h));
  SceneSetup setup;
  std::vector<sb::RootSpeeds> speeds;
  std::vector<float> rootSpeed;
  for (const anim::ClipPair& c : anim::defaultClipSets()) {
    setup.pairs.push_back(anim::makeMotionPair(c.slow, c.fast));
    speeds.push_back({anim::clipRootSpeed(setup.pairs.back().slow),
                      anim::clipRootSpeed(setup.pairs.back().fast)});
    rootSpeed.push_back(speeds.back().fast);
  }
  sb::PlacementOptions place;
  place.cellSize = d.cell;
  place.seed = d.seed;
  place.jitter = 0.05f;
  place.actionSpeeds.emplace();
  std::copy_n(speeds.begin(), sb::kActionCount, place.actionSpeeds->begin());
  const sb::Placement placed = sb::placeStoryboard(board, place);
  setup.crowd = placed.crowd;
  setup.tints = placed.tint;
  setup.labels = placed.tint;
  // One group per clip set that has agents (pairs of empty sets are dropped).
  std::vector<anim::MotionPair> pairs = std::move(setup.pairs);
  setup.pairs.clear();
  setup.groupFirst = {0};
  for (size_t k = 0; k < pairs.size(); ++k) {
    if (placed.setBegin[k + 1] == setup.groupFirst.back()) continue;
    setup.pairs.push_back(std::move(pairs[k]));
    setup.groupFirst.push_back(placed.setBegin[k + 1]);
  }
  // The walls run 6 m past each end, around the goal areas, so that nobody pushed out of an end
  // walks round the outside of a wall.
  const float x = 0.5f * d.length + 6.0f, z = 0.5f * d.width;
  setup.walls.addPolyline(std::vector<glm::vec2>{{-x, -z}, {x, -z}}, false);
  setup.walls.addPolyline(std::vector<glm::vec2>{{-x, z}, {x, z}}, false);
  setup.steering.emplace();
  setup.steering->avoidance = d.avoidance;
  setup.steering->goals = corridorGoals(d, setup.crowd, rootSpeed, setup.crowd.clipSet);
  return setup;
}

}  // namespace throng::scene
