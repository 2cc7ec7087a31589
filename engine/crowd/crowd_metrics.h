#pragma once
// How a simulated crowd compares with real pedestrians (issue 6, part 6):
//   * collisions per agent-second: a collision is the moment two bodies start to overlap
//     (distance < 2·body radius, kBodyRadius = 0.2 m by default); it counts once for each of
//     the two agents;
//   * safe-radius intrusions per agent-second, counted the same way at the avoidance's safe
//     radius (0.3 m): people walking side by side come that close without touching, so this
//     is a separate figure, not a collision;
//   * speed distribution: the two-sample Kolmogorov–Smirnov distance between the agents'
//     per-second speeds and the source people's |P_ij|;
//   * path error: distance between an agent and the waypoint its path vectors put it at, at
//     every whole second (how far avoidance pushed it off its source's path);
//   * density: the peak number of agents per m² in 2 m × 2 m cells.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "crowd/trajectories.h"

namespace throng::crowd {

// Radius of a person's body for counting collisions (shoulder half-width plus a little).
inline constexpr float kBodyRadius = 0.2f;

// sup |F_a − F_b| of the empirical distributions (0 identical, 1 disjoint; 0 when either is empty).
double ksDistance(std::span<const float> a, std::span<const float> b);

// Counts overlap onsets step by step. Positions are placement vec4s (x, y, z, heading);
// inactive agents are skipped.
class CollisionCounter {
 public:
  explicit CollisionCounter(float radius) : radius_(radius) {}
  void addStep(std::span<const glm::vec4> placement, std::span<const uint8_t> active, float dt);

  uint64_t collisions() const { return collisions_; }  // agent events (2 per pair onset)
  double agentSeconds() const { return agentSeconds_; }
  double perAgentSecond() const {
    return agentSeconds_ > 0.0 ? double(collisions_) / agentSeconds_ : 0.0;
  }
  double overlapShare() const {
    return agentSteps_ ? double(overlapAgentSteps_) / double(agentSteps_) : 0.0;
  }
  double peakDensity() const { return peakDensity_; }

 private:
  float radius_;
  std::vector<uint64_t> previous_;  // sorted pair keys (i << 32 | j, i < j) overlapping last step
  uint64_t collisions_ = 0;
  double agentSeconds_ = 0.0;
  uint64_t agentSteps_ = 0, overlapAgentSteps_ = 0;
  double peakDensity_ = 0.0;
};

struct CrowdMetrics {
  double seconds = 0.0;
  size_t agents = 0;
  double agentSeconds = 0.0;
  float bodyRadius = kBodyRadius;  // m, collisions
  float safeRadius = 0.0f;         // m, intrusions
  uint64_t collisions = 0;
  double collisionsPerAgentSecond = 0.0;
  double overlapShare = 0.0;    // share of agent-steps spent overlapping someone's body
  uint64_t safeIntrusions = 0;  // agent events at the safe radius
  double safeIntrusionsPerAgentSecond = 0.0;
  double speedKs = 0.0;    // KS distance, agent vs source per-second speeds
  double meanSpeed = 0.0;  // agents (m/s)
  double sourceMeanSpeed = 0.0;
  size_t speedSamples = 0;
  double meanPathError = 0.0;  // m
  double p95PathError = 0.0;
  double maxPathError = 0.0;
  double peakDensity = 0.0;  // agents / m²
};

// Collisions (at bodyRadius), safe-radius intrusions, speeds and density of the real people
// themselves, sampled at every annotated frame (speeds: the one-second path vectors), for
// comparison with a simulation.
CrowdMetrics trajectoryMetrics(const Trajectories& trajectories, float safeRadius,
                               float bodyRadius = kBodyRadius);

// Fills the collision, intrusion and density figures of `m` from the two counters.
void setContactMetrics(CrowdMetrics& m, const CollisionCounter& body, float bodyRadius,
                       const CollisionCounter& safe, float safeRadius);

std::string formatMetrics(const std::string& label, const CrowdMetrics& m);
std::string metricsJson(const CrowdMetrics& m);  // one JSON object

}  // namespace throng::crowd
