#include "crowd/nav_mesh.h"

#include <algorithm>
#include <limits>
#include <queue>

#include "core/error.h"
#include "menge/menge.h"

// Road maps (nav_mesh.h): a graph of way points searched by A*, entered and left by visibility
// against the scene's walls.
namespace throng::crowd {

namespace {
constexpr float kUnreached = std::numeric_limits<float>::infinity();  // no path found yet
}  // namespace

RoadMap makeRoadMap(std::vector<glm::vec2> points,
                    const std::vector<std::pair<uint32_t, uint32_t>>& edges) {
  RoadMap map;
  map.points = std::move(points);
  map.neighbors.resize(map.points.size());
  for (const auto& [a, b] : edges) {
    if (a >= map.points.size() || b >= map.points.size())
      fail("road map: edge ", a, "-", b, " names a way point of ", map.points.size());
    map.neighbors[a].push_back(b);
    map.neighbors[b].push_back(a);
  }
  return map;
}

RoadMap roadMapFromMenge(const menge::RoadMap& map) {
  return makeRoadMap(map.vertices, map.edges);
}

namespace {

// The nearest way point visible from p, or the nearest one when none is.
uint32_t nearestWayPoint(const RoadMap& map, glm::vec2 p) {
  uint32_t best = 0, bestVisible = 0;
  bool anyVisible = false;
  for (uint32_t i = 0; i < map.points.size(); ++i) {
    const float d = glm::distance(map.points[i], p);
    if (d < glm::distance(map.points[best], p)) best = i;
    if ((!anyVisible || d < glm::distance(map.points[bestVisible], p)) &&
        visible(map.walls, p, map.points[i])) {
      bestVisible = i;
      anyVisible = true;
    }
  }
  return anyVisible ? bestVisible : best;
}

}  // namespace

bool visible(std::span<const Segment> walls, glm::vec2 p, glm::vec2 q) {
  for (const Segment& w : walls)
    if (segmentsCross(p, q, w.a, w.b)) return false;
  return true;
}

PlannedPath planOnRoadMap(const RoadMap& map, glm::vec2 start, glm::vec2 target) {
  PlannedPath path;
  if (map.empty() || start == target || (!map.walls.empty() && visible(map.walls, start, target))) {
    path.points = {start, target};
    return path;
  }
  const uint32_t s = nearestWayPoint(map, start);
  uint32_t g = nearestWayPoint(map, target);
  const size_t n = map.points.size();
  std::vector<float> cost(n, kUnreached);
  std::vector<int32_t> parent(n, -1);
  std::vector<bool> closed(n, false);
  using Item = std::pair<float, uint32_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  cost[s] = 0.0f;
  open.push({glm::distance(map.points[s], map.points[g]), s});
  while (!open.empty()) {
    const uint32_t p = open.top().second;
    open.pop();
    if (closed[p]) continue;
    closed[p] = true;
    if (p == g) break;
    for (uint32_t q : map.neighbors[p]) {
      const float c = cost[p] + glm::distance(map.points[p], map.points[q]);
      if (closed[q] || c >= cost[q]) continue;
      cost[q] = c;
      parent[q] = int32_t(p);
      open.push({c + glm::distance(map.points[q], map.points[g]), q});
    }
  }
  glm::vec2 end = target;
  if (!closed[g]) {
    // Unreachable: end at the reached way point nearest the target.
    for (uint32_t i = 0; i < n; ++i)
      if (closed[i] && (!closed[g] || glm::distance(map.points[i], target) <
                                          glm::distance(map.points[g], target)))
        g = i;
    end = map.points[g];
    path.partial = true;
  }
  for (int32_t p = int32_t(g); p >= 0; p = parent[p]) path.points.push_back(map.points[p]);
  path.points.push_back(start);
  std::reverse(path.points.begin(), path.points.end());
  if (path.points.back() != end) path.points.push_back(end);
  return path;
}

}  // namespace throng::crowd
