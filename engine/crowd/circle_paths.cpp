#include "crowd/circle_paths.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/math.h"
#include "shaders/shared_types.h"

namespace throng::crowd {
namespace {

// Waypoints of one lap of radius r in n seconds, from angle 0: r·(cos jω − 1, sin jω).
std::vector<glm::vec2> lapCumulative(float radius, uint32_t seconds) {
  std::vector<glm::vec2> sums;
  const double step = 2.0 * double(kPi) / double(seconds);
  for (uint32_t j = 0; j < seconds; ++j)
    sums.push_back(float(radius) *
                   glm::vec2(float(std::cos(step * j) - 1.0), float(std::sin(step * j))));
  sums.push_back(glm::vec2(0.0f));  // back at the start: the waypoints repeat every lap
  return sums;
}

}  // namespace

AgentPaths circlePaths(const Crowd& crowd, float slowSpeed, float fastSpeed) {
  if (!(slowSpeed > 0.0f && fastSpeed > 0.0f))
    fail("circle paths: the clip pair's root speeds must be positive, got ", slowSpeed, " and ",
         fastSpeed);
  AgentPaths paths;
  std::map<std::pair<int64_t, uint32_t>, uint32_t> sourceOf;  // (radius in mm, lap seconds)
  for (size_t i = 0; i < crowd.size(); ++i) {
    const glm::vec2 p(crowd.placement[i].x, crowd.placement[i].z);
    const float radius = glm::length(p);
    if (!(radius > 0.5f))
      fail("circle paths: runner ", i, " stands ", radius, " m from the centre (expected > 0.5 m)");
    const float w = std::clamp(gpu_types::speedWeight(crowd.motion[i]), 0.0f, 1.0f);
    const float speed = slowSpeed + w * (fastSpeed - slowSpeed);
    const uint32_t lap =
        uint32_t(std::clamp(std::lround(2.0 * double(kPi) * radius / speed), 3L, 100000L));
    const auto key = std::make_pair(int64_t(std::llround(double(radius) * 1000.0)), lap);
    auto [it, added] = sourceOf.try_emplace(key, uint32_t(paths.cumulative.size()));
    if (added) paths.cumulative.push_back(lapCumulative(float(key.first) / 1000.0f, lap));
    const float angle = std::atan2(p.y, p.x);
    paths.source.push_back(it->second);
    paths.start.push_back(p);
    paths.rotation.push_back({std::cos(angle), std::sin(angle)});
    paths.maxSpeed.push_back(1.25f * 2.0f * kPi * radius / float(lap));
    paths.firstSecond.push_back(0);
    paths.lastSecond.push_back(std::numeric_limits<uint32_t>::max());
  }
  return paths;
}

uint32_t countClosePairs(std::span<const glm::vec4> placement, float distance) {
  const float inv = 1.0f / distance;
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
  auto key = [](int64_t x, int64_t z) {
    return (uint64_t(uint32_t(int32_t(x))) << 32) | uint32_t(int32_t(z));
  };
  for (size_t i = 0; i < placement.size(); ++i)
    cells[key(int64_t(std::floor(placement[i].x * inv)), int64_t(std::floor(placement[i].z * inv)))]
        .push_back(uint32_t(i));
  uint32_t pairs = 0;
  for (size_t i = 0; i < placement.size(); ++i) {
    const int64_t cx = int64_t(std::floor(placement[i].x * inv)),
                  cz = int64_t(std::floor(placement[i].z * inv));
    for (int64_t dz = -1; dz <= 1; ++dz)
      for (int64_t dx = -1; dx <= 1; ++dx) {
        auto it = cells.find(key(cx + dx, cz + dz));
        if (it == cells.end()) continue;
        for (uint32_t j : it->second) {
          if (j <= i) continue;
          const glm::vec2 d(placement[i].x - placement[j].x, placement[i].z - placement[j].z);
          pairs += glm::dot(d, d) < distance * distance;
        }
      }
  }
  return pairs;
}

SteeredCrowdCpu::SteeredCrowdCpu(const anim::MotionPair& pair, Crowd crowd, const AgentPaths* paths,
                                 const AvoidanceParams& params)
    : pair_(pair), crowd_(std::move(crowd)), paths_(paths), params_(params) {
  const size_t n = crowd_.size();
  if (paths_ && paths_->size() != n)
    fail("steered crowd: ", n, " agents but ", paths_->size(), " paths");
  goals_.assign(n, glm::vec4(0.0f));
  steer_.assign(n, glm::vec4(0.0f));
  frame_.sets = {{anim::clipRootSpeed(pair.slow), anim::clipRootSpeed(pair.fast), uint32_t(n)}};
}

void SteeredCrowdCpu::step(float dt, const anim::SpeedRetarget& retarget) {
  const size_t n = crowd_.size();
  if (paths_) {
    const int64_t second = int64_t(std::floor(time_));
    if (second != goalSecond_) writeGoals(*paths_, uint32_t(second), goals_);
    goalSecond_ = second;
    frame_.dt = dt;
    frame_.secondsLeft = std::max(float(double(second + 1) - time_), 1e-3f);
    frame_.step = steps_;
    const Grid grid =
        buildGridCpu(crowd_.placement, steer_, params_.cellSize, gridTable(uint32_t(n)));
    steerCpu(grid, params_, frame_, crowd_.placement, crowd_.motion, goals_, steer_);
  }
  const anim::Steering steering = paths_ ? anim::Steering::KeepHeading : crowd_.steering;
  for (size_t i = 0; i < n; ++i)
    anim::stepCharacter(pair_, crowd_.placement[i], crowd_.motion[i], dt, steering, retarget,
                        uint32_t(i));
  ++steps_;
  time_ = double(steps_) * double(dt);
}

CircleRunFigures runCircleCpu(const anim::MotionPair& pair, Crowd crowd, const AgentPaths* paths,
                              const AvoidanceParams& params, float dt, float seconds) {
  const size_t n = crowd.size();
  std::vector<float> startRadius(n);
  for (size_t i = 0; i < n; ++i)
    startRadius[i] = glm::length(glm::vec2(crowd.placement[i].x, crowd.placement[i].z));
  SteeredCrowdCpu run(pair, std::move(crowd), paths, params);
  CircleRunFigures figures;
  figures.minClosePairs = std::numeric_limits<uint32_t>::max();
  const int steps = int(std::lround(double(seconds) / double(dt)));
  double closeSum = 0.0;
  for (int k = 0; k < steps; ++k) {
    run.step(dt);
    const uint32_t close = countClosePairs(run.crowd().placement, 0.6f);
    figures.minClosePairs = std::min(figures.minClosePairs, close);
    figures.maxClosePairs = std::max(figures.maxClosePairs, close);
    closeSum += close;
  }
  for (size_t i = 0; i < n; ++i) {
    const glm::vec4& p = run.crowd().placement[i];
    const double drift = double(glm::length(glm::vec2(p.x, p.z))) - startRadius[i];
    figures.meanRadiusDrift += drift / double(n);
    figures.meanAbsRadiusError += std::abs(drift) / double(n);
  }
  figures.meanClosePairs = steps > 0 ? closeSum / double(steps) : 0.0;
  if (steps == 0) figures.minClosePairs = 0;
  return figures;
}

}  // namespace throng::crowd
