#include "crowd/path_vectors.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/rng.h"

namespace throng::crowd {
namespace {

// Data (x, y) seen from above → world (x, z = −y), so a replay is not a mirror image.
glm::vec2 toWorld(glm::vec2 p) {
  return {p.x, -p.y};
}

glm::vec2 positionAt(const Track& track, double time) {
  const auto& pts = track.points;
  auto after = std::lower_bound(pts.begin(), pts.end(), time,
                                [](const TrackPoint& p, double t) { return p.time < t; });
  if (after == pts.begin()) return pts.front().position;
  if (after == pts.end()) return pts.back().position;
  const TrackPoint& a = *(after - 1);
  const TrackPoint& b = *after;
  float u = float((time - a.time) / (b.time - a.time));
  return a.position + (b.position - a.position) * u;
}

glm::vec2 rotate(glm::vec2 rotation, glm::vec2 v) {
  return {rotation.x * v.x - rotation.y * v.y, rotation.y * v.x + rotation.x * v.y};
}

// Unit rotation taking the source's overall travel onto direction `to` (world x, z).
glm::vec2 alignRotation(const std::vector<glm::vec2>& cumulative, glm::vec2 to) {
  glm::vec2 from = cumulative.back();
  if (glm::length(from) < 0.5f) {
    // Nearly back where it started: the longest single step gives the direction instead.
    from = glm::vec2(0.0f);
    for (size_t j = 1; j < cumulative.size(); ++j) {
      glm::vec2 step = cumulative[j] - cumulative[j - 1];
      if (glm::length(step) > glm::length(from)) from = step;
    }
  }
  if (glm::length(from) < 1e-3f) return {1.0f, 0.0f};
  float angle = std::atan2(to.y, to.x) - std::atan2(from.y, from.x);
  return {std::cos(angle), std::sin(angle)};
}

std::vector<glm::vec2> cumulativeOf(const PathSource& source) {
  std::vector<glm::vec2> sums(1, glm::vec2(0.0f));
  for (glm::vec2 v : source.vectors) sums.push_back(sums.back() + v);
  return sums;
}

}  // namespace

float PathSource::meanSpeed() const {
  if (vectors.empty()) return 0.0f;
  double sum = 0.0;
  for (glm::vec2 v : vectors) sum += glm::length(v);
  return float(sum / double(vectors.size()));
}

std::vector<PathSource> resamplePathVectors(const Trajectories& trajectories) {
  const double t0 = trajectories.startTime();
  const double eps = 1e-4;
  std::vector<PathSource> sources;
  for (const Track& track : trajectories.tracks) {
    if (track.points.size() < 2) continue;
    long first = long(std::ceil(track.points.front().time - t0 - eps));
    long last = long(std::floor(track.points.back().time - t0 + eps));
    if (last - first < 1) continue;
    if (last > long(std::numeric_limits<int32_t>::max()))
      fail(trajectories.source, ": person ", track.id, " is annotated ", last,
           " s after the file's first sample (expected under 2^31 s)");
    PathSource source;
    source.id = track.id;
    source.startSecond = uint32_t(std::max(0L, first));
    glm::vec2 previous = toWorld(positionAt(track, t0 + double(first)));
    source.start = previous;
    for (long k = first + 1; k <= last; ++k) {
      glm::vec2 p = toWorld(positionAt(track, t0 + double(k)));
      source.vectors.push_back(p - previous);
      previous = p;
    }
    sources.push_back(std::move(source));
  }
  return sources;
}

std::vector<float> pathSpeeds(std::span<const PathSource> sources) {
  std::vector<float> speeds;
  for (const PathSource& s : sources)
    for (glm::vec2 v : s.vectors) speeds.push_back(glm::length(v));
  return speeds;
}

std::vector<uint32_t> assignSources(std::span<const PathSource> sources,
                                    std::span<const SpeedRange> agentRanges, uint64_t seed,
                                    std::string_view origin) {
  if (sources.empty())
    fail(origin,
         ": no tracked person to take path vectors from (expected a track spanning two whole "
         "seconds)");
  std::vector<uint32_t> bySpeed(sources.size());
  std::vector<float> speeds(sources.size());
  for (size_t k = 0; k < sources.size(); ++k)
    bySpeed[k] = uint32_t(k), speeds[k] = sources[k].meanSpeed();
  std::stable_sort(bySpeed.begin(), bySpeed.end(),
                   [&](uint32_t a, uint32_t b) { return speeds[a] < speeds[b]; });
  std::vector<float> sorted(sources.size());
  for (size_t k = 0; k < bySpeed.size(); ++k) sorted[k] = speeds[bySpeed[k]];
  Rng rng(seed, 0x9a7b);
  std::vector<uint32_t> chosen(agentRanges.size());
  for (size_t i = 0; i < agentRanges.size(); ++i) {
    const SpeedRange r = agentRanges[i];
    size_t lo = size_t(std::lower_bound(sorted.begin(), sorted.end(), r.min) - sorted.begin());
    size_t hi = size_t(std::upper_bound(sorted.begin(), sorted.end(), r.max) - sorted.begin());
    uint32_t pick = rng.next();
    if (hi > lo) {
      chosen[i] = bySpeed[lo + pick % (hi - lo)];
    } else {
      // No source in range: the slowest above it or the fastest below it, whichever is nearer.
      size_t k = lo < sorted.size() && (lo == 0 || sorted[lo] - r.max < r.min - sorted[lo - 1])
                     ? lo
                     : lo - 1;
      chosen[i] = bySpeed[k];
    }
  }
  return chosen;
}

float speedWeight(float speed, float slowSpeed, float fastSpeed) {
  if (!(fastSpeed > slowSpeed)) return 0.0f;
  return std::clamp((speed - slowSpeed) / (fastSpeed - slowSpeed), 0.0f, 1.0f);
}

glm::vec2 AgentPaths::waypoint(size_t agent, uint32_t j) const {
  const std::vector<glm::vec2>& c = cumulative[source[agent]];
  const uint32_t n = uint32_t(c.size() - 1);
  if (holds(source[agent])) j = std::min(j, n);
  glm::vec2 offset = j <= n ? c[j] : float(j / n) * c[n] + c[j % n];
  return start[agent] + rotate(rotation[agent], offset);
}

AgentPaths followSources(const Crowd& crowd, std::span<const PathSource> sources,
                         std::span<const uint32_t> source, std::span<const float> maxSpeed) {
  if (source.size() != crowd.size() || maxSpeed.size() != crowd.size())
    fail("followSources: ", crowd.size(), " agents but ", source.size(), " sources and ",
         maxSpeed.size(), " speeds");
  AgentPaths paths;
  for (const PathSource& s : sources) {
    if (s.vectors.empty()) fail("path source ", s.id, " has no path vector");
    paths.cumulative.push_back(cumulativeOf(s));
  }
  const size_t n = crowd.size();
  paths.source.assign(source.begin(), source.end());
  paths.maxSpeed.assign(maxSpeed.begin(), maxSpeed.end());
  paths.firstSecond.assign(n, 0);
  paths.lastSecond.assign(n, std::numeric_limits<uint32_t>::max());
  for (size_t i = 0; i < n; ++i) {
    if (source[i] >= sources.size())
      fail("agent ", i, " follows source ", source[i], " of ", sources.size());
    const glm::vec4 p = crowd.placement[i];
    paths.start.push_back({p.x, p.z});
    paths.rotation.push_back(
        alignRotation(paths.cumulative[source[i]], {std::sin(p.w), std::cos(p.w)}));
  }
  return paths;
}

AgentPaths replaySources(std::span<const PathSource> sources, glm::vec2 origin, float maxSpeed) {
  AgentPaths paths;
  for (size_t i = 0; i < sources.size(); ++i) {
    const PathSource& s = sources[i];
    if (s.vectors.empty()) fail("path source ", s.id, " has no path vector");
    paths.cumulative.push_back(cumulativeOf(s));
    paths.source.push_back(uint32_t(i));
    paths.start.push_back(s.start - origin);
    paths.rotation.push_back({1.0f, 0.0f});
    paths.maxSpeed.push_back(maxSpeed);
    paths.firstSecond.push_back(s.startSecond);
    paths.lastSecond.push_back(s.startSecond + uint32_t(s.vectors.size()));
  }
  return paths;
}

void writeGoals(const AgentPaths& paths, uint32_t second, std::span<glm::vec4> goals) {
  THRONG_CHECK(goals.size() >= paths.size(), "goal buffer smaller than the crowd");
  for (size_t i = 0; i < paths.size(); ++i) {
    if (!paths.active(i, second)) {
      goals[i] = glm::vec4(0.0f);
      continue;
    }
    glm::vec2 w = paths.waypoint(i, second - paths.firstSecond[i] + 1);
    goals[i] = glm::vec4(w.x, w.y, paths.maxSpeed[i], 1.0f);
  }
}

}  // namespace throng::crowd
