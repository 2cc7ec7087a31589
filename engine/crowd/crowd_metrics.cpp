#include "crowd/crowd_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>

#include "core/error.h"
#include "crowd/avoidance.h"
#include "crowd/path_vectors.h"

namespace throng::crowd {

double ksDistance(std::span<const float> a, std::span<const float> b) {
  if (a.empty() || b.empty()) return 0.0;
  std::vector<float> x(a.begin(), a.end()), y(b.begin(), b.end());
  std::sort(x.begin(), x.end());
  std::sort(y.begin(), y.end());
  size_t i = 0, j = 0;
  double worst = 0.0;
  while (i < x.size() && j < y.size()) {
    float v = std::min(x[i], y[j]);
    while (i < x.size() && x[i] == v) ++i;  // step past ties in both before comparing
    while (j < y.size() && y[j] == v) ++j;
    worst = std::max(worst, std::abs(double(i) / double(x.size()) - double(j) / double(y.size())));
  }
  return worst;
}

void CollisionCounter::addStep(std::span<const glm::vec4> placement,
                               std::span<const uint8_t> active, float dt) {
  THRONG_CHECK(active.size() == placement.size(), "one active flag per agent expected");
  const float diameter = 2.0f * radius_;
  const float cell = std::max(diameter, 2.0f);
  const glm::vec2 inv(1.0f / cell);
  // Buckets of active agents by cell (exact coordinates: no hash collisions to sort out).
  std::unordered_map<uint64_t, std::vector<uint32_t>> cells;
  auto key = [](glm::ivec2 c) { return (uint64_t(uint32_t(c.x)) << 32) | uint32_t(c.y); };
  size_t activeCount = 0;
  for (size_t i = 0; i < placement.size(); ++i) {
    if (!active[i]) continue;
    ++activeCount;
    cells[key(cellCoord({placement[i].x, placement[i].z}, inv))].push_back(uint32_t(i));
  }
  // Density over the counting cells (2 m unless the safe diameter is larger).
  for (const auto& [k, members] : cells)
    peakDensity_ = std::max(peakDensity_, double(members.size()) / (cell * cell));
  std::vector<uint64_t> current;
  std::vector<uint8_t> overlapping(placement.size(), 0);
  for (const auto& [k, members] : cells) {
    for (uint32_t i : members) {
      glm::vec2 p(placement[i].x, placement[i].z);
      glm::ivec2 home = cellCoord(p, inv);
      for (int dz = -1; dz <= 1; ++dz)
        for (int dx = -1; dx <= 1; ++dx) {
          auto it = cells.find(key(home + glm::ivec2(dx, dz)));
          if (it == cells.end()) continue;
          for (uint32_t j : it->second) {
            if (j <= i) continue;
            glm::vec2 d = p - glm::vec2(placement[j].x, placement[j].z);
            if (glm::dot(d, d) < diameter * diameter) {
              current.push_back((uint64_t(i) << 32) | j);
              overlapping[i] = overlapping[j] = 1;
            }
          }
        }
    }
  }
  std::sort(current.begin(), current.end());
  for (uint64_t pair : current)
    if (!std::binary_search(previous_.begin(), previous_.end(), pair)) collisions_ += 2;
  previous_ = std::move(current);
  agentSeconds_ += double(activeCount) * dt;
  agentSteps_ += activeCount;
  for (uint8_t o : overlapping) overlapAgentSteps_ += o;
}

void setContactMetrics(CrowdMetrics& m, const CollisionCounter& body, float bodyRadius,
                       const CollisionCounter& safe, float safeRadius) {
  m.bodyRadius = bodyRadius;
  m.safeRadius = safeRadius;
  m.agentSeconds = body.agentSeconds();
  m.collisions = body.collisions();
  m.collisionsPerAgentSecond = body.perAgentSecond();
  m.overlapShare = body.overlapShare();
  m.safeIntrusions = safe.collisions();
  m.safeIntrusionsPerAgentSecond = safe.perAgentSecond();
  m.peakDensity = std::max(body.peakDensity(), safe.peakDensity());
}

CrowdMetrics trajectoryMetrics(const Trajectories& trajectories, float safeRadius,
                               float bodyRadius) {
  // Every annotated frame as one step of the real crowd.
  std::map<long long, std::vector<glm::vec2>> frames;
  const double spf = trajectories.secondsPerFrame;
  for (const Track& track : trajectories.tracks)
    for (const TrackPoint& p : track.points)
      frames[std::llround(p.time / spf)].push_back(p.position);
  CollisionCounter body(bodyRadius), safe(safeRadius);
  for (const auto& [frame, positions] : frames) {
    std::vector<glm::vec4> placement;
    for (glm::vec2 p : positions) placement.push_back(glm::vec4(p.x, 0.0f, p.y, 0.0f));
    std::vector<uint8_t> active(placement.size(), 1);
    body.addStep(placement, active, float(trajectories.secondsPerStep));
    safe.addStep(placement, active, float(trajectories.secondsPerStep));
  }
  CrowdMetrics m;
  m.agents = trajectories.tracks.size();
  m.seconds = frames.empty() ? 0.0 : double(frames.rbegin()->first - frames.begin()->first) * spf;
  setContactMetrics(m, body, bodyRadius, safe, safeRadius);
  std::vector<float> speeds = pathSpeeds(resamplePathVectors(trajectories));
  m.speedSamples = speeds.size();
  double sum = 0.0;
  for (float s : speeds) sum += s;
  m.meanSpeed = m.sourceMeanSpeed = speeds.empty() ? 0.0 : sum / double(speeds.size());
  return m;
}

namespace {
// A measurement with a fixed number of decimals: as many as the figure can tell apart.
std::string withDecimals(double x, int decimals) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, x);
  return text;
}
}  // namespace

// Rates per agent-second take 4 decimals (they are around 0.01), percentages, speeds, distances
// and densities 2, the KS distance 3. Radii are settings and print as given.
std::string formatMetrics(const std::string& label, const CrowdMetrics& m) {
  return concat(label, ": ", m.agents, " agents, ", m.seconds, " s, ",
                withDecimals(m.agentSeconds, 0), " agent-s\n", "  collisions per agent-second ",
                withDecimals(m.collisionsPerAgentSecond, 4), " at body radius ", m.bodyRadius,
                " m (", m.collisions, " agent events), overlapping ",
                withDecimals(100.0 * m.overlapShare, 2), " % of agent-steps\n", "  safe-radius (",
                m.safeRadius, " m) intrusions per agent-second ",
                withDecimals(m.safeIntrusionsPerAgentSecond, 4), " (", m.safeIntrusions,
                " agent events)\n", "  speed: mean ", withDecimals(m.meanSpeed, 2),
                " m/s (sources ", withDecimals(m.sourceMeanSpeed, 2), " m/s), KS distance ",
                withDecimals(m.speedKs, 3), " over ", m.speedSamples, " samples\n",
                "  path error: mean ", withDecimals(m.meanPathError, 2), " m, p95 ",
                withDecimals(m.p95PathError, 2), " m, max ", withDecimals(m.maxPathError, 2),
                " m\n", "  peak density ", withDecimals(m.peakDensity, 2), " agents/m^2\n");
}

std::string metricsJson(const CrowdMetrics& m) {
  return concat("{\"agents\":", m.agents, ",\"seconds\":", m.seconds,
                ",\"agent_seconds\":", m.agentSeconds, ",\"body_radius\":", m.bodyRadius,
                ",\"safe_radius\":", m.safeRadius, ",\"collisions\":", m.collisions,
                ",\"safe_intrusions\":", m.safeIntrusions,
                ",\"safe_intrusions_per_agent_second\":", m.safeIntrusionsPerAgentSecond,
                ",\"collisions_per_agent_second\":", m.collisionsPerAgentSecond,
                ",\"overlap_share\":", m.overlapShare, ",\"speed_ks\":", m.speedKs,
                ",\"mean_speed\":", m.meanSpeed, ",\"source_mean_speed\":", m.sourceMeanSpeed,
                ",\"speed_samples\":", m.speedSamples, ",\"mean_path_error\":", m.meanPathError,
                ",\"p95_path_error\":", m.p95PathError, ",\"max_path_error\":", m.maxPathError,
                ",\"peak_density\":", m.peakDensity, "}");
}

}  // namespace throng::crowd
