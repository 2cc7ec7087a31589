#include "scene/corridor_scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "anim/default_clips.h"
#include "core/error.h"
#include "core/log.h"
#include "core/rng.h"
#include "crowd/goals.h"
#include "crowd/trajectories.h"
#include "storyboard/codec.h"
#include "storyboard/example.h"
#include "storyboard/legend.h"
#include "storyboard/quilt.h"
#include "storyboard/storyboard_placement.h"

namespace throng::scene {
namespace sb = throng::storyboard;

namespace {

constexpr int kMaxPixels = 16 << 20;
// Waypoints stay this far from the walls (a body radius and a step), so no path leads into one.
constexpr float kWallClearance = 0.75f;
// A walker's path is at most this many seconds long (a source goes ≥ 3 m per repetition).
constexpr size_t kMaxWalkSeconds = 100000;

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

// Tracked people a walker can copy: those who went somewhere (3 m or more, along a path at most
// 25 % longer than the straight line), so that turning their overall direction along the
// corridor makes them walk along it.
std::vector<crowd::PathSource> walkingSources(const std::string& file) {
  std::vector<crowd::PathSource> walking;
  for (crowd::PathSource& s : crowd::resamplePathVectors(crowd::loadTrajectories(file))) {
    glm::vec2 net(0.0f);
    float along = 0.0f;
    for (glm::vec2 v : s.vectors) net += v, along += glm::length(v);
    if (glm::length(net) >= 3.0f && glm::length(net) >= 0.8f * along)
      walking.push_back(std::move(s));
  }
  return walking;
}

// z reflected into [lo, hi], as a mirror at each wall would.
float fold(float z, float lo, float hi) {
  const float span = hi - lo;
  const float t = std::fmod(std::fmod(z - lo, 2.0f * span) + 2.0f * span, 2.0f * span);
  return lo + (t <= span ? t : 2.0f * span - t);
}

glm::vec2 rotated(glm::vec2 r, glm::vec2 v) {
  return {r.x * v.x - r.y * v.y, r.y * v.x + r.x * v.y};
}

// One walker's path from `start`: the source's vectors turned by `r` (rotation and scale), over
// and over, with z folded into the corridor, until x is `endX` past the centre in direction
// `dir`; the last waypoint is on that line. Partial sums from the start (entry 0 is 0).
std::vector<glm::vec2> walkToEnd(const crowd::PathSource& source, glm::vec2 r, glm::vec2 start,
                                 float dir, float endX, float halfWidth) {
  const float lo = -halfWidth + kWallClearance, hi = halfWidth - kWallClearance;
  std::vector<glm::vec2> sums{glm::vec2(0.0f)};
  glm::vec2 q = start;  // unfolded
  for (size_t j = 0;; ++j) {
    if (sums.size() > kMaxWalkSeconds)
      fail("corridor: tracked person ", source.id, " does not get to the far end");
    q += rotated(r, source.vectors[j % source.vectors.size()]);
    glm::vec2 p(q.x, fold(q.y, lo, hi));
    const bool there = dir * p.x >= endX;
    if (there) p.x = dir * endX;
    sums.push_back(p - start);
    if (there) return sums;
  }
}

// Every agent's path: walkers (clip sets that travel) copy a tracked person of their speed
// range to the end their glyph faces; the others stand where they are (source 0, no motion).
crowd::AgentPaths corridorPaths(const CorridorDescription& d, const sb::Placement& placed,
                                std::span<const sb::RootSpeeds> speeds,
                                std::span<const crowd::PathSource> sources) {
  const crowd::Crowd& crowd = placed.crowd;
  const std::vector<uint32_t> assigned =
      crowd::assignSources(sources, placed.speedRange, d.seed, d.trajectories);
  size_t toEnd[2] = {0, 0};  // walkers to +x, to −x
  for (size_t i = 0; i < crowd.size(); ++i)
    if (speeds[crowd.clipSet[i]].fast > 0.0f)
      ++toEnd[std::sin(crowd.placement[i].w) >= 0.0f ? 0 : 1];
  const float depth[2] = {corridorStopDepth(toEnd[0], d.width),
                          corridorStopDepth(toEnd[1], d.width)};
  crowd::AgentPaths paths;
  paths.cumulative.push_back({glm::vec2(0.0f), glm::vec2(0.0f)});
  paths.holdsEnd.push_back(1);
  Rng rng(d.seed, 0xc0ad);
  for (size_t i = 0; i < crowd.size(); ++i) {
    const glm::vec4 p = crowd.placement[i];
    const sb::RootSpeeds r = speeds[crowd.clipSet[i]];
    paths.start.push_back({p.x, p.z});
    paths.rotation.push_back({1.0f, 0.0f});
    paths.firstSecond.push_back(0);
    paths.lastSecond.push_back(UINT32_MAX);
    if (!(r.fast > 0.0f)) {
      paths.source.push_back(0);
      paths.maxSpeed.push_back(0.0f);
      continue;
    }
    const crowd::PathSource& s = sources[assigned[i]];
    glm::vec2 net(0.0f);
    for (glm::vec2 v : s.vectors) net += v;
    const float dir = std::sin(p.w) >= 0.0f ? 1.0f : -1.0f;
    const float stop = rng.uniform(0.5f, depth[dir > 0.0f ? 0 : 1]);
    const glm::vec2 u = glm::normalize(net);
    const float mean = s.meanSpeed();
    const float scale = mean > 0.05f ? std::clamp(mean, r.slow, r.fast) / mean : 1.0f;
    // (cos, sin) turning u onto (dir, 0), times the speed scale.
    const glm::vec2 turn = scale * glm::vec2(dir * u.x, -dir * u.y);
    paths.source.push_back(uint32_t(paths.cumulative.size()));
    paths.cumulative.push_back(
        walkToEnd(s, turn, {p.x, p.z}, dir, 0.5f * d.length + stop, 0.5f * d.width));
    paths.holdsEnd.push_back(1);
    paths.maxSpeed.push_back(1.25f * r.fast);
  }
  return paths;
}

// Path vectors from the tracked set when it is there and has walkers, else goals.
void addCorridorSteering(const CorridorDescription& d, const sb::Placement& placed,
                         std::span<const sb::RootSpeeds> speeds,
                         const std::vector<float>& rootSpeed, SceneSetup& setup) {
  setup.steering.emplace();
  setup.steering->avoidance = d.avoidance;
  const bool tracked = !d.trajectories.empty() && std::filesystem::exists(d.trajectories);
  const std::vector<crowd::PathSource> sources =
      tracked ? walkingSources(d.trajectories) : std::vector<crowd::PathSource>{};
  if (!sources.empty()) {
    setup.steering->paths = corridorPaths(d, placed, speeds, sources);
    logInfo(concat("corridor: ", setup.crowd.size(), " agents; walkers follow the path vectors of ",
                   sources.size(), " tracked people of ", d.trajectories));
  } else {
    logWarning(concat(
        "corridor: ", d.trajectories.empty() ? std::string("no tracked set") : d.trajectories,
        tracked ? " has nobody walking 3 m or more" : " is absent",
        "; walkers head for the far end by goals instead of path vectors"));
    setup.steering->goals = corridorGoals(d, setup.crowd, rootSpeed, setup.crowd.clipSet);
  }
}

// The walls run past each end around the walkers' stops, so that nobody pushed out of an end
// walks round the outside of a wall (at least 6 m, also for goals).
void addCorridorWalls(const CorridorDescription& d, SceneSetup& setup) {
  const std::vector<int> dirs = corridorDirections(setup);
  const float reach[2] = {
      corridorWallReach(size_t(std::count(dirs.begin(), dirs.end(), -1)), d.width),
      corridorWallReach(size_t(std::count(dirs.begin(), dirs.end(), 1)), d.width)};
  const float x0 = -0.5f * d.length - reach[0], x1 = 0.5f * d.length + reach[1];
  const float z = 0.5f * d.width;
  setup.walls.addPolyline(std::vector<glm::vec2>{{x0, -z}, {x1, -z}}, false);
  setup.walls.addPolyline(std::vector<glm::vec2>{{x0, z}, {x1, z}}, false);
}

}  // namespace

float corridorStopDepth(size_t walkersToEnd, float width) {
  const float usable = std::max(width - 2.0f * kWallClearance, 1.0f);
  return std::max(4.0f, 0.5f + float(walkersToEnd) / (kCorridorArrivalDensity * usable));
}

float corridorWallReach(size_t walkersToEnd, float width) {
  return std::max(6.0f, corridorStopDepth(walkersToEnd, width) + 2.0f);
}

std::vector<int> corridorDirections(const SceneSetup& corridor) {
  std::vector<int> dirs(corridor.crowd.size(), 0);
  if (!corridor.steering) return dirs;
  const SteeringSetup& s = *corridor.steering;
  for (size_t i = 0; i < dirs.size(); ++i) {
    if (s.goals) {
      const uint32_t g = s.goals->agentGroup[i];
      dirs[i] = g == crowd::kNoState ? 0 : g == 0 ? 1 : -1;
    } else if (i < s.paths.size()) {
      const float x = s.paths.cumulative[s.paths.source[i]].back().x;
      dirs[i] = x > 0.0f ? 1 : x < 0.0f ? -1 : 0;
    }
  }
  return dirs;
}

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
  addCorridorSteering(d, placed, speeds, rootSpeed, setup);
  addCorridorWalls(d, setup);
  return setup;
}

}  // namespace throng::scene
