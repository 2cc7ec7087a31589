#include "crowd/nav_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

#include "core/error.h"
#include "menge/menge.h"

namespace throng::crowd {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

float cross2(glm::vec2 a, glm::vec2 b) {
  return a.x * b.y - a.y * b.x;
}
// > 0: c lies left of the ray a → b (counter-clockwise in (x, z) taken as (x, y)).
float side(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
  return cross2(b - a, c - a);
}

glm::vec2 closestOnEdge(glm::vec2 a, glm::vec2 b, glm::vec2 p) {
  const glm::vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return a + t * ab;
}

glm::vec2 vertexOf(const NavMesh& mesh, const NavPolygon& poly, size_t k) {
  return mesh.vertices[poly.vertices[k % poly.vertices.size()]];
}

bool contains(const NavMesh& mesh, const NavPolygon& poly, glm::vec2 p, float tolerance) {
  if (p.x < poly.lo.x - tolerance || p.y < poly.lo.y - tolerance || p.x > poly.hi.x + tolerance ||
      p.y > poly.hi.y + tolerance)
    return false;
  for (size_t k = 0; k < poly.vertices.size(); ++k) {
    const glm::vec2 a = vertexOf(mesh, poly, k), b = vertexOf(mesh, poly, k + 1);
    if (side(a, b, p) < -tolerance * glm::length(b - a)) return false;
  }
  return true;
}

glm::vec2 closestOnPolygon(const NavMesh& mesh, uint32_t polygon, glm::vec2 p) {
  const NavPolygon& poly = mesh.polygons[polygon];
  if (contains(mesh, poly, p, 0.0f)) return p;
  glm::vec2 best = vertexOf(mesh, poly, 0);
  for (size_t k = 0; k < poly.vertices.size(); ++k) {
    const glm::vec2 q = closestOnEdge(vertexOf(mesh, poly, k), vertexOf(mesh, poly, k + 1), p);
    if (glm::distance(q, p) < glm::distance(best, p)) best = q;
  }
  return best;
}

// Makes the polygon counter-clockwise and checks it is convex (a little slack for the rounding
// of meshes written as text).
void orientAndCheck(const std::vector<glm::vec2>& v, std::vector<uint32_t>& poly, size_t index) {
  if (poly.size() < 3)
    fail("nav mesh: polygon ", index, " has ", poly.size(), " vertices, 3+ needed");
  for (uint32_t i : poly)
    if (i >= v.size()) fail("nav mesh: polygon ", index, " names vertex ", i, " of ", v.size());
  double area = 0.0;
  for (size_t k = 0; k < poly.size(); ++k)
    area += cross2(v[poly[k]], v[poly[(k + 1) % poly.size()]]);
  if (!(std::abs(area) > 1e-9)) fail("nav mesh: polygon ", index, " has no area");
  if (area < 0.0) std::reverse(poly.begin(), poly.end());
  for (size_t k = 0; k < poly.size(); ++k) {
    const glm::vec2 a = v[poly[k]], b = v[poly[(k + 1) % poly.size()]],
                    c = v[poly[(k + 2) % poly.size()]];
    const float scale = glm::length(b - a) * glm::length(c - b);
    if (side(a, b, c) < -1e-3f * scale)
      fail("nav mesh: polygon ", index, " is not convex at vertex ", poly[(k + 1) % poly.size()]);
  }
}

void buildLookupGrid(NavMesh& mesh) {
  glm::vec2 lo(kInfinity), hi(-kInfinity);
  for (const NavPolygon& p : mesh.polygons) {
    lo = glm::min(lo, p.lo);
    hi = glm::max(hi, p.hi);
  }
  const glm::vec2 extent = glm::max(hi - lo, glm::vec2(1e-3f));
  const float cells = std::max(1.0f, std::sqrt(float(mesh.polygons.size())));
  mesh.gridCell = std::max(extent.x, extent.y) / cells;
  mesh.gridOrigin = lo;
  mesh.gridSize = glm::clamp(glm::ivec2(glm::ceil(extent / mesh.gridCell)), 1, 1024);
  mesh.gridCell = std::max(extent.x / float(mesh.gridSize.x), extent.y / float(mesh.gridSize.y));
  const size_t cellCount = size_t(mesh.gridSize.x) * size_t(mesh.gridSize.y);
  std::vector<std::vector<uint32_t>> lists(cellCount);
  auto cellOf = [&](glm::vec2 p) {
    return glm::clamp(glm::ivec2(glm::floor((p - lo) / mesh.gridCell)), glm::ivec2(0),
                      mesh.gridSize - 1);
  };
  for (uint32_t i = 0; i < mesh.polygons.size(); ++i) {
    const glm::ivec2 a = cellOf(mesh.polygons[i].lo), b = cellOf(mesh.polygons[i].hi);
    for (int y = a.y; y <= b.y; ++y)
      for (int x = a.x; x <= b.x; ++x) lists[size_t(y) * mesh.gridSize.x + x].push_back(i);
  }
  mesh.cellStart.assign(cellCount + 1, 0);
  for (size_t c = 0; c < cellCount; ++c) {
    mesh.cellStart[c + 1] = mesh.cellStart[c] + uint32_t(lists[c].size());
    mesh.cellPolygons.insert(mesh.cellPolygons.end(), lists[c].begin(), lists[c].end());
  }
}

// Where an A* over polygons stands: per polygon the cost so far, the way in and its entry point.
struct PolygonSearch {
  std::vector<float> cost;
  std::vector<int32_t> parent;
  std::vector<glm::vec2> entry;
  std::vector<bool> closed;
};

// A* from polygon s to g; returns false when g cannot be reached.
bool searchPolygons(const NavMesh& mesh, int s, int g, glm::vec2 start, glm::vec2 target,
                    PolygonSearch& search) {
  const size_t n = mesh.polygons.size();
  search.cost.assign(n, kInfinity);
  search.parent.assign(n, -1);
  search.entry.assign(n, start);
  search.closed.assign(n, false);
  using Item = std::pair<float, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  search.cost[s] = 0.0f;
  open.push({glm::distance(start, target), s});
  while (!open.empty()) {
    const int p = open.top().second;
    open.pop();
    if (search.closed[p]) continue;
    search.closed[p] = true;
    if (p == g) return true;
    const NavPolygon& poly = mesh.polygons[p];
    for (size_t k = 0; k < poly.vertices.size(); ++k) {
      const int q = poly.neighbors[k];
      if (q < 0 || search.closed[q]) continue;
      const glm::vec2 mid = 0.5f * (vertexOf(mesh, poly, k) + vertexOf(mesh, poly, k + 1));
      const float cost = search.cost[p] + glm::distance(search.entry[p], mid);
      if (cost >= search.cost[q]) continue;
      search.cost[q] = cost;
      search.parent[q] = p;
      search.entry[q] = mid;
      open.push({cost + glm::distance(mid, target), q});
    }
  }
  return false;
}

// The portal from polygon a into its neighbour b: (left, right) walking from a to b.
std::pair<glm::vec2, glm::vec2> portal(const NavMesh& mesh, uint32_t a, uint32_t b) {
  const NavPolygon& poly = mesh.polygons[a];
  for (size_t k = 0; k < poly.vertices.size(); ++k)
    if (poly.neighbors[k] == int32_t(b))
      return {vertexOf(mesh, poly, k + 1), vertexOf(mesh, poly, k)};
  fail("nav mesh: polygons ", a, " and ", b, " are not neighbours");
}

}  // namespace

NavMesh makeNavMesh(std::vector<glm::vec2> vertices,
                    const std::vector<std::vector<uint32_t>>& polygons) {
  NavMesh mesh;
  mesh.vertices = std::move(vertices);
  for (glm::vec2 v : mesh.vertices)
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) fail("nav mesh: a vertex is not finite");
  std::unordered_map<uint64_t, std::pair<uint32_t, uint32_t>> edges;  // key → (polygon, edge)
  for (size_t i = 0; i < polygons.size(); ++i) {
    NavPolygon poly;
    poly.vertices = polygons[i];
    orientAndCheck(mesh.vertices, poly.vertices, i);
    poly.neighbors.assign(poly.vertices.size(), -1);
    poly.lo = poly.hi = mesh.vertices[poly.vertices[0]];
    for (uint32_t v : poly.vertices) {
      poly.lo = glm::min(poly.lo, mesh.vertices[v]);
      poly.hi = glm::max(poly.hi, mesh.vertices[v]);
    }
    mesh.polygons.push_back(std::move(poly));
  }
  for (uint32_t i = 0; i < mesh.polygons.size(); ++i) {
    NavPolygon& poly = mesh.polygons[i];
    for (uint32_t k = 0; k < poly.vertices.size(); ++k) {
      const uint32_t a = poly.vertices[k], b = poly.vertices[(k + 1) % poly.vertices.size()];
      const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      auto [it, inserted] = edges.try_emplace(key, i, k);
      if (inserted) continue;
      const auto [j, e] = it->second;
      if (poly.neighbors[k] >= 0 || mesh.polygons[j].neighbors[e] >= 0)
        fail("nav mesh: edge ", a, "-", b, " is shared by more than two polygons");
      poly.neighbors[k] = int32_t(j);
      mesh.polygons[j].neighbors[e] = int32_t(i);
    }
  }
  if (!mesh.polygons.empty()) buildLookupGrid(mesh);
  return mesh;
}

NavMesh navMeshFromMenge(const menge::NavMesh& mesh) {
  std::vector<std::vector<uint32_t>> polygons;
  polygons.reserve(mesh.nodes.size());
  for (const menge::NavMesh::Node& node : mesh.nodes) polygons.push_back(node.polygon);
  NavMesh out;
  try {
    out = makeNavMesh(mesh.vertices, polygons);
  } catch (const Error& e) {
    fail(mesh.source.string(), ": ", e.what());
  }
  // Menge lists its portals as edges between nodes, which may join polygons whose vertex
  // indices differ (a vertex written twice): those edges decide the adjacency.
  for (const menge::NavMesh::Edge& e : mesh.edges) {
    const glm::vec2 a = mesh.vertices[e.v0], b = mesh.vertices[e.v1];
    for (auto [p, q] : {std::pair{e.node0, e.node1}, std::pair{e.node1, e.node0}}) {
      NavPolygon& poly = out.polygons[p];
      for (size_t k = 0; k < poly.vertices.size(); ++k) {
        const glm::vec2 u = vertexOf(out, poly, k), w = vertexOf(out, poly, k + 1);
        if ((u == a && w == b) || (u == b && w == a)) poly.neighbors[k] = int32_t(q);
      }
    }
  }
  return out;
}

int findPolygon(const NavMesh& mesh, glm::vec2 p, float tolerance) {
  if (mesh.empty()) return -1;
  const glm::ivec2 c = glm::ivec2(glm::floor((p - mesh.gridOrigin) / mesh.gridCell));
  if (c.x < -1 || c.y < -1 || c.x > mesh.gridSize.x || c.y > mesh.gridSize.y) return -1;
  const glm::ivec2 cell = glm::clamp(c, glm::ivec2(0), mesh.gridSize - 1);
  const size_t index = size_t(cell.y) * mesh.gridSize.x + cell.x;
  for (uint32_t k = mesh.cellStart[index]; k < mesh.cellStart[index + 1]; ++k)
    if (contains(mesh, mesh.polygons[mesh.cellPolygons[k]], p, tolerance))
      return int(mesh.cellPolygons[k]);
  return -1;
}

glm::vec2 closestMeshPoint(const NavMesh& mesh, glm::vec2 p, int* polygon) {
  int found = findPolygon(mesh, p, 0.0f);
  glm::vec2 best = p;
  if (found < 0) {
    float bestDistance = kInfinity;
    for (uint32_t i = 0; i < mesh.polygons.size(); ++i) {
      const glm::vec2 q = closestOnPolygon(mesh, i, p);
      if (glm::distance(q, p) < bestDistance) {
        bestDistance = glm::distance(q, p);
        best = q;
        found = int(i);
      }
    }
  }
  if (polygon) *polygon = found;
  return best;
}

std::vector<glm::vec2> funnelPath(glm::vec2 start, glm::vec2 target,
                                  const std::vector<std::pair<glm::vec2, glm::vec2>>& portals) {
  std::vector<std::pair<glm::vec2, glm::vec2>> all;
  all.reserve(portals.size() + 2);
  all.push_back({start, start});
  all.insert(all.end(), portals.begin(), portals.end());
  all.push_back({target, target});
  std::vector<glm::vec2> points = {start};
  glm::vec2 apex = start, left = start, right = start;
  size_t apexIndex = 0, leftIndex = 0, rightIndex = 0;
  for (size_t i = 1; i < all.size(); ++i) {
    const auto [l, r] = all[i];
    // The right edge narrows when r is not outside it; r past the left edge makes the left
    // point a corner of the path (and symmetrically).
    if (side(apex, right, r) >= 0.0f) {
      if (apex == right || side(apex, left, r) < 0.0f) {
        right = r;
        rightIndex = i;
      } else {
        if (points.back() != left) points.push_back(left);
        apex = right = left;
        apexIndex = rightIndex = leftIndex;
        i = apexIndex;
        continue;
      }
    }
    if (side(apex, left, l) <= 0.0f) {
      if (apex == left || side(apex, right, l) > 0.0f) {
        left = l;
        leftIndex = i;
      } else {
        if (points.back() != right) points.push_back(right);
        apex = left = right;
        apexIndex = leftIndex = rightIndex;
        i = apexIndex;
        continue;
      }
    }
  }
  if (points.back() != target) points.push_back(target);
  return points;
}

namespace {

// Moves each corner of the path `clearance` metres off the wall vertex it turns around, towards
// the outside of the turn, where that point is still on the mesh (else half as far, else not).
void keepClear(const NavMesh& mesh, std::vector<glm::vec2>& points, float clearance) {
  if (!(clearance > 0.0f)) return;
  const std::vector<glm::vec2> original = points;
  for (size_t k = 1; k + 1 < points.size(); ++k) {
    const glm::vec2 in = original[k] - original[k - 1], out = original[k + 1] - original[k];
    if (glm::length(in) < 1e-6f || glm::length(out) < 1e-6f) continue;
    const glm::vec2 away = glm::normalize(in) - glm::normalize(out);
    if (glm::length(away) < 1e-4f) continue;
    for (float d : {clearance, 0.5f * clearance}) {
      const glm::vec2 moved = original[k] + d * glm::normalize(away);
      if (findPolygon(mesh, moved, 0.0f) >= 0) {
        points[k] = moved;
        break;
      }
    }
  }
}

}  // namespace

PlannedPath planOnNavMesh(const NavMesh& mesh, glm::vec2 start, glm::vec2 target, float clearance) {
  PlannedPath path;
  if (mesh.empty()) {
    path.points = {start, target};
    return path;
  }
  int s = findPolygon(mesh, start), g = findPolygon(mesh, target);
  glm::vec2 from = start, to = target;
  if (s < 0) from = closestMeshPoint(mesh, start, &s);
  if (g < 0) to = closestMeshPoint(mesh, target, &g);
  path.partial = from != start || to != target;
  PolygonSearch search;
  if (!searchPolygons(mesh, s, g, from, to, search)) {
    // Unreachable: the closest point to the target of the polygons the start reaches.
    float best = kInfinity;
    for (uint32_t i = 0; i < mesh.polygons.size(); ++i) {
      if (!search.closed[i]) continue;
      const glm::vec2 q = closestOnPolygon(mesh, i, to);
      if (glm::distance(q, to) < best) {
        best = glm::distance(q, to);
        g = int(i);
        to = q;
      }
    }
    path.partial = true;
  }
  for (int p = g; p >= 0; p = search.parent[p]) path.corridor.push_back(uint32_t(p));
  std::reverse(path.corridor.begin(), path.corridor.end());
  std::vector<std::pair<glm::vec2, glm::vec2>> portals;
  for (size_t k = 0; k + 1 < path.corridor.size(); ++k)
    portals.push_back(portal(mesh, path.corridor[k], path.corridor[k + 1]));
  path.points = funnelPath(from, to, portals);
  keepClear(mesh, path.points, clearance);
  if (from != start) path.points.insert(path.points.begin(), start);
  return path;
}

bool segmentsCross(glm::vec2 p, glm::vec2 q, glm::vec2 a, glm::vec2 b) {
  const float pa = side(p, q, a), pb = side(p, q, b), ap = side(a, b, p), aq = side(a, b, q);
  return ((pa <= 0.0f && pb >= 0.0f) || (pa >= 0.0f && pb <= 0.0f)) &&
         ((ap <= 0.0f && aq >= 0.0f) || (ap >= 0.0f && aq <= 0.0f)) &&
         !(pa == 0.0f && pb == 0.0f);  // collinear: passing along a wall's line is not crossing
}

bool visibleOnMesh(const NavMesh& mesh, glm::vec2 p, glm::vec2 q) {
  constexpr float kTolerance = 1e-3f;
  int poly = findPolygon(mesh, p, kTolerance), from = -1;
  // Each step leaves a convex polygon through the edge the segment crosses towards q.
  for (size_t steps = 0; poly >= 0 && steps <= mesh.polygons.size(); ++steps) {
    const NavPolygon& current = mesh.polygons[size_t(poly)];
    if (contains(mesh, current, q, kTolerance)) return true;
    int next = -1;
    bool exited = false;
    for (size_t k = 0; k < current.vertices.size() && !exited; ++k) {
      const glm::vec2 a = vertexOf(mesh, current, k), b = vertexOf(mesh, current, k + 1);
      if (current.neighbors[k] == from && from >= 0) continue;
      if (side(a, b, q) >= 0.0f || !segmentsCross(p, q, a, b)) continue;
      next = current.neighbors[k];
      exited = true;
    }
    if (!exited || next < 0) return false;  // through a wall edge
    from = poly;
    poly = next;
  }
  return false;
}

float remainingPathLength(std::span<const glm::vec2> path, glm::vec2 p) {
  if (path.size() < 2) return path.empty() ? 0.0f : glm::distance(p, path.back());
  // Backwards, so that of equally near points the one farther along the path counts.
  float nearest = kInfinity, remaining = 0.0f, tail = 0.0f;
  for (size_t k = path.size() - 1; k > 0; --k) {
    const glm::vec2 q = closestOnEdge(path[k - 1], path[k], p);
    if (glm::distance(p, q) < nearest) {
      nearest = glm::distance(p, q);
      remaining = nearest + glm::distance(q, path[k]) + tail;
    }
    tail += glm::distance(path[k - 1], path[k]);
  }
  return remaining;
}

PlannedPath planPath(const NavMesh& mesh, const RoadMap& map, glm::vec2 start, glm::vec2 target,
                     float clearance) {
  if (!mesh.empty()) return planOnNavMesh(mesh, start, target, clearance);
  return planOnRoadMap(map, start, target);
}

}  // namespace throng::crowd
