#include "crowd/obstacles.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace throng::crowd {

void Obstacles::addPolyline(std::span<const glm::vec2> points, bool closed) {
  const size_t least = closed ? 3 : 2;
  if (points.size() < least)
    fail(closed ? "polygon" : "polyline", " of ", points.size(), " points: at least ", least,
         " expected");
  for (size_t k = 0; k + 1 < points.size(); ++k) segments.push_back({points[k], points[k + 1]});
  if (closed) segments.push_back({points.back(), points.front()});
}

namespace {

// Appends the runs of consecutive edges: edge k of the line lies from `start + k · step` to the
// next, and is a wall where `isEdge(k)`.
template <typename IsEdge>
void addRuns(std::vector<Segment>& out, uint32_t count, glm::vec2 start, glm::vec2 step,
             IsEdge isEdge) {
  uint32_t k = 0;
  while (k < count) {
    if (!isEdge(k)) {
      ++k;
      continue;
    }
    uint32_t end = k;
    while (end < count && isEdge(end)) ++end;
    out.push_back({start + float(k) * step, start + float(end) * step});
    k = end;
  }
}

}  // namespace

void Obstacles::addWalkableGrid(const WalkableGrid& g) {
  if (!(g.cellSize > 0.0f) || !std::isfinite(g.cellSize))
    fail("walkable grid: cell size ", g.cellSize, " m: expected a positive size");
  if (g.columns == 0 || g.rows == 0 || size_t(g.columns) * g.rows != g.walkable.size())
    fail("walkable grid: ", g.columns, " x ", g.rows, " cells but ", g.walkable.size(),
         " values: expected one per cell");
  auto open = [&](int64_t c, int64_t r) {
    return c >= 0 && r >= 0 && c < g.columns && r < g.rows &&
           g.walkable[size_t(r) * g.columns + size_t(c)] != 0;
  };
  const float s = g.cellSize;
  for (uint32_t r = 0; r <= g.rows; ++r)  // edges between rows r − 1 and r, along x
    addRuns(segments, g.columns, g.origin + glm::vec2(0.0f, float(r) * s), {s, 0.0f},
            [&](uint32_t c) { return open(c, int64_t(r) - 1) != open(c, r); });
  for (uint32_t c = 0; c <= g.columns; ++c)  // edges between columns c − 1 and c, along z
    addRuns(segments, g.rows, g.origin + glm::vec2(float(c) * s, 0.0f), {0.0f, s},
            [&](uint32_t r) { return open(int64_t(c) - 1, r) != open(c, r); });
}

std::vector<std::string> validateObstacles(const Obstacles& o) {
  std::vector<std::string> problems;
  if (o.segments.size() > kMaxSegments)
    problems.push_back(
        concat(o.segments.size(), " wall segments: at most ", kMaxSegments, " are supported"));
  for (size_t k = 0; k < o.segments.size() && problems.size() < 8; ++k) {
    const Segment& s = o.segments[k];
    bool finite = std::isfinite(s.a.x) && std::isfinite(s.a.y) && std::isfinite(s.b.x) &&
                  std::isfinite(s.b.y);
    float extent = std::max({std::abs(s.a.x), std::abs(s.a.y), std::abs(s.b.x), std::abs(s.b.y)});
    if (!finite || extent > kMaxWallCoordinate)
      problems.push_back(concat("wall segment ", k, " (", s.a.x, ", ", s.a.y, ") - (", s.b.x, ", ",
                                s.b.y, "): coordinates must be finite and within +-",
                                kMaxWallCoordinate, " m"));
    else if (glm::length(s.b - s.a) < kMinSegmentLength)
      problems.push_back(concat("wall segment ", k, " at (", s.a.x, ", ", s.a.y,
                                ") is degenerate: shorter than ", kMinSegmentLength, " m"));
  }
  return problems;
}

uint32_t WallGrid::cellOf(glm::vec2 p) const {
  // Multiplied by the reciprocal as the shaders do, so both pick the same cell.
  const glm::vec2 f = glm::floor((p - origin) * (1.0f / cellSize));
  if (!(f.x >= 0.0f && f.y >= 0.0f && f.x < float(columns) && f.y < float(rows))) return UINT32_MAX;
  return uint32_t(f.y) * columns + uint32_t(f.x);
}

namespace {

// Calls visit(cell) for every cell that may lie within reach of segment s: the cells of its
// bounding box grown by reach whose centre is within reach + half a diagonal of the segment (a
// superset of the cells within reach, and exact enough to keep long diagonal walls cheap).
template <typename Visit>
void forCellsNear(const WallGrid& g, const Segment& s, Visit visit) {
  const float inv = 1.0f / g.cellSize;
  const glm::vec2 lo = (glm::min(s.a, s.b) - g.reach - g.origin) * inv;
  const glm::vec2 hi = (glm::max(s.a, s.b) + g.reach - g.origin) * inv;
  const int c0 = std::max(0, int(std::floor(lo.x))), r0 = std::max(0, int(std::floor(lo.y)));
  const int c1 = std::min(int(g.columns) - 1, int(std::floor(hi.x)));
  const int r1 = std::min(int(g.rows) - 1, int(std::floor(hi.y)));
  const float within = g.reach + 0.7072f * g.cellSize;
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      glm::vec2 centre = g.origin + (glm::vec2(float(c), float(r)) + 0.5f) * g.cellSize;
      glm::vec2 off = centre - closestOnSegment(centre, s.a, s.b);
      if (glm::dot(off, off) <= within * within) visit(uint32_t(r) * g.columns + uint32_t(c));
    }
}

bool segmentsMeet(glm::vec2 p, glm::vec2 q, glm::vec2 a, glm::vec2 b);  // below

// The distance between segment s and the cell [lo, hi] (0 where they meet), less a margin for
// the rounding of the cell's corners and of the shaders' own distances.
float cellDistance(const Segment& s, glm::vec2 lo, glm::vec2 hi) {
  auto inside = [&](glm::vec2 p) {
    return glm::all(glm::greaterThanEqual(p, lo)) && glm::all(glm::lessThanEqual(p, hi));
  };
  if (inside(s.a) || inside(s.b)) return 0.0f;
  const glm::vec2 corners[] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
  float d = kNoWallHit;
  for (int k = 0; k < 4; ++k) {
    const glm::vec2 c = corners[k], e = corners[(k + 1) % 4];
    if (segmentsMeet(s.a, s.b, c, e)) return 0.0f;
    d = std::min(d, glm::length(c - closestOnSegment(c, s.a, s.b)));
  }
  for (glm::vec2 p : {s.a, s.b}) d = std::min(d, glm::length(p - glm::clamp(p, lo, hi)));
  return std::max(d - 1e-3f, 0.0f);
}

}  // namespace

WallGrid binObstacles(const Obstacles& o, float cellSize, float reach, size_t maxEntries) {
  const std::vector<std::string> problems = validateObstacles(o);
  if (!problems.empty()) fail("walls: ", problems.front());
  if (!(cellSize > 0.0f && reach > 0.0f) || !std::isfinite(cellSize) || !std::isfinite(reach))
    fail("wall grid: cell size ", cellSize, " and reach ", reach, " m must be positive");
  WallGrid g;
  g.cellSize = cellSize;
  g.reach = reach;
  g.segments = o.segments;
  glm::vec2 lo(0.0f), hi(0.0f);
  if (!o.segments.empty()) lo = hi = o.segments.front().a;
  for (const Segment& s : o.segments) {
    lo = glm::min(lo, glm::min(s.a, s.b));
    hi = glm::max(hi, glm::max(s.a, s.b));
  }
  g.origin = lo - reach;
  const glm::vec2 cells = glm::ceil((hi + reach - g.origin) / cellSize);
  if (double(cells.x) * double(cells.y) > double(kMaxWallCells))
    fail("walls span ", hi.x - lo.x, " x ", hi.y - lo.y, " m: ", double(cells.x) * cells.y,
         " grid cells of ", cellSize, " m, at most ", kMaxWallCells, " (use larger cells)");
  g.columns = std::max(1u, uint32_t(cells.x));
  g.rows = std::max(1u, uint32_t(cells.y));
  // Counting pass first, so a scene over the budget fails before anything large is allocated.
  std::vector<uint32_t> counts(size_t(g.columns) * g.rows, 0);
  size_t entries = 0;
  for (const Segment& s : o.segments)
    forCellsNear(g, s, [&](uint32_t cell) {
      ++counts[cell];
      if (++entries > maxEntries)
        fail("walls: binning ", o.segments.size(), " segments into ", cellSize,
             " m cells needs more than ", maxEntries, " entries (the budget): fewer or shorter ",
             "segments, or a smaller sensing range");
    });
  g.starts.assign(counts.size() + 1, 0);
  for (size_t c = 0; c < counts.size(); ++c) g.starts[c + 1] = g.starts[c] + counts[c];
  g.indices.resize(entries);
  std::vector<uint32_t> cursor(g.starts.begin(), g.starts.end() - 1);
  g.clearance.assign(counts.size(), reach);
  for (size_t k = 0; k < o.segments.size(); ++k)
    forCellsNear(g, o.segments[k], [&](uint32_t cell) {
      g.indices[cursor[cell]++] = uint32_t(k);
      const glm::vec2 lo =
          g.origin + glm::vec2(float(cell % g.columns), float(cell / g.columns)) * g.cellSize;
      g.clearance[cell] =
          std::min(g.clearance[cell], cellDistance(o.segments[k], lo, lo + g.cellSize));
    });
  return g;
}

glm::vec2 closestOnSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
  const glm::vec2 d = b - a;
  const float dd = glm::dot(d, d);
  const float u = dd > 0.0f ? std::clamp(glm::dot(p - a, d) / dd, 0.0f, 1.0f) : 0.0f;
  return a + u * d;
}

namespace {

// The first touch of the disc with the end disc at e (radius r): the smaller root of
// |p − e + t m|² = r², in the form without cancellation (as ttcForce's τ).
float endHit(glm::vec2 p, glm::vec2 m, glm::vec2 e, float r) {
  const glm::vec2 x = p - e;
  // c < 0 only by rounding here (the caller found the disc outside): a touch now.
  const float b = glm::dot(x, m), mm = glm::dot(m, m), c = std::max(glm::dot(x, x) - r * r, 0.0f);
  const float disc = b * b - mm * c;
  if (!(b < 0.0f && disc >= 0.0f && mm > 0.0f)) return kNoWallHit;
  return c / (std::sqrt(disc) - b);
}

}  // namespace

float segmentHit(glm::vec2 p, glm::vec2 m, glm::vec2 a, glm::vec2 b, float r, glm::vec2& normal) {
  normal = glm::vec2(0.0f);
  const glm::vec2 off = p - closestOnSegment(p, a, b);
  const float d2 = glm::dot(off, off);
  if (d2 < r * r) {
    // Moving along or away from the closest point never brings a disc closer to a segment
    // (the distance to a convex set is convex along a line); a tolerance for rounding in slides.
    if (d2 > 1e-12f) normal = off / std::sqrt(d2);
    return glm::dot(m, normal) < -1e-5f * glm::length(m) || d2 <= 1e-12f ? 0.0f : kNoWallHit;
  }
  float t = kNoWallHit;
  const glm::vec2 d = b - a;
  const float len2 = glm::dot(d, d);
  glm::vec2 side = glm::normalize(glm::vec2(-d.y, d.x));
  float s0 = glm::dot(p - a, side);
  if (s0 < 0.0f) side = -side, s0 = -s0;
  const float sv = glm::dot(m, side);
  // The side of the capsule facing the disc; s0 < r only by rounding (the closest point's
  // distance said outside): a touch now, as the inside test would have said.
  if (sv < 0.0f) {
    const float ts = std::max(s0 - r, 0.0f) / -sv;
    const float u = glm::dot(p + ts * m - a, d);
    if (u >= 0.0f && u <= len2) t = ts, normal = side;
  }
  for (glm::vec2 e : {a, b}) {
    const float te = endHit(p, m, e, r);
    if (te < t) t = te, normal = glm::normalize(p + te * m - e);
  }
  return t;
}

glm::vec2 constrainMove(const WallGrid& walls, glm::vec2 from, glm::vec2 to, float radius) {
  const uint32_t cell = walls.cellOf(from);
  glm::vec2 m = to - from;
  const float maxMove = walls.reach - radius;
  const float length = glm::length(m);
  const bool shortened = length > maxMove;
  if (shortened) m *= maxMove / length;
  if (cell == UINT32_MAX) return shortened ? from + m : to;
  const float r = radius + kWallSkin;
  const float screen = r + glm::length(m);  // no slide of this move reaches farther segments
  if (cell < walls.clearance.size() && walls.clearance[cell] > screen)  // as the shader
    return shortened ? from + m : to;
  glm::vec2 p = from;
  for (int contact = 0; contact < 3; ++contact) {
    float first = kNoWallHit;
    glm::vec2 normal(0.0f);
    for (uint32_t k = walls.starts[cell]; k < walls.starts[cell + 1]; ++k) {
      const Segment& s = walls.segments[walls.indices[k]];
      const glm::vec2 off = from - closestOnSegment(from, s.a, s.b);
      if (glm::dot(off, off) > screen * screen) continue;
      glm::vec2 n;
      const float t = segmentHit(p, m, s.a, s.b, r, n);
      if (t < first) first = t, normal = n;
    }
    if (first > 1.0f) return contact == 0 && !shortened ? to : p + m;
    if (normal == glm::vec2(0.0f)) return p;  // on the segment itself: no tangent to slide on
    p += first * m;
    const glm::vec2 rest = (1.0f - first) * m;
    m = rest - glm::dot(rest, normal) * normal;
  }
  return p;
}

void wallConstraintCpu(const WallGrid& walls, float radius, std::span<const glm::vec4> previous,
                       std::span<glm::vec4> placement, uint32_t first, uint32_t count) {
  THRONG_CHECK(size_t(first) + count <= placement.size() && previous.size() >= placement.size(),
               "wallConstraintCpu: agents ", first, " + ", count, " of ", placement.size());
  for (uint32_t i = first; i < first + count; ++i) {
    glm::vec2 p = constrainMove(walls, {previous[i].x, previous[i].z},
                                {placement[i].x, placement[i].z}, radius);
    placement[i].x = p.x;
    placement[i].z = p.y;
  }
}

namespace {

// Whether the closed segments pq and ab share a point (in double, so the check is exact enough
// to judge the float passes).
bool segmentsMeet(glm::vec2 p, glm::vec2 q, glm::vec2 a, glm::vec2 b) {
  auto orient = [](glm::dvec2 o, glm::dvec2 u, glm::dvec2 v) {
    double c = (u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x);
    return c > 0.0 ? 1 : c < 0.0 ? -1 : 0;
  };
  glm::dvec2 P(p), Q(q), A(a), B(b);
  int o1 = orient(P, Q, A), o2 = orient(P, Q, B), o3 = orient(A, B, P), o4 = orient(A, B, Q);
  // Collinear touching is a distance of 0, which the distance check counts.
  return o1 != o2 && o3 != o4;
}

// The check's own binning of the segments (not the WallGrid's lists, which are part of what it
// checks): square cells, each listing every segment that passes through it, so a box of cells
// holds every segment that comes within the box.
class SegmentBins {
 public:
  explicit SegmentBins(std::span<const Segment> segments) {
    glm::vec2 lo(kNoWallHit), hi(-kNoWallHit);
    for (const Segment& s : segments) {
      lo = glm::min(lo, glm::min(s.a, s.b));
      hi = glm::max(hi, glm::max(s.a, s.b));
    }
    // About 16k cells over the walls' bounding box, none smaller than half a metre.
    const glm::vec2 extent = glm::max(hi - lo, glm::vec2(0.0f));
    cell_ = std::max(0.5f, std::sqrt(extent.x * extent.y / 16384.0f));
    cell_ = std::max(cell_, std::max(extent.x, extent.y) / 4096.0f);
    origin_ = lo;
    columns_ = int(extent.x / cell_) + 1;
    rows_ = int(extent.y / cell_) + 1;
    std::vector<std::pair<uint32_t, uint32_t>> pairs;  // (cell, segment)
    for (uint32_t i = 0; i < segments.size(); ++i)
      forCellsOf(segments[i], [&](int cell) { pairs.emplace_back(uint32_t(cell), i); });
    std::sort(pairs.begin(), pairs.end());
    starts_.assign(size_t(columns_) * rows_ + 1, 0);
    for (const auto& [cell, segment] : pairs) ++starts_[cell + 1];
    for (size_t c = 1; c < starts_.size(); ++c) starts_[c] += starts_[c - 1];
    for (const auto& pair : pairs) items_.push_back(pair.second);
  }

  // Calls visit(segment) for the segments listed in the cells overlapping [lo, hi] (a segment
  // in several cells more than once).
  template <class Visit>
  void forEachNear(glm::vec2 lo, glm::vec2 hi, Visit visit) const {
    const glm::ivec2 a = cellClamped(lo), b = cellClamped(hi);
    for (int r = a.y; r <= b.y; ++r)
      for (int c = a.x; c <= b.x; ++c) {
        const size_t cell = size_t(r) * columns_ + c;
        for (uint32_t k = starts_[cell]; k < starts_[cell + 1]; ++k) visit(items_[k]);
      }
  }

 private:
  glm::ivec2 cellClamped(glm::vec2 p) const {
    const glm::vec2 f = glm::clamp((p - origin_) / cell_, glm::vec2(0.0f),
                                   glm::vec2(float(columns_ - 1), float(rows_ - 1)));
    return glm::ivec2(f);
  }
  // The cells a segment passes through: per row of cells, the columns of its part in that row.
  template <class Visit>
  void forCellsOf(const Segment& s, Visit visit) const {
    const glm::vec2 a = (s.a - origin_) / cell_, b = (s.b - origin_) / cell_;
    const int firstRow = cellClamped(glm::min(s.a, s.b)).y,
              lastRow = cellClamped(glm::max(s.a, s.b)).y;
    for (int r = firstRow; r <= lastRow; ++r) {
      float t0 = 0.0f, t1 = 1.0f;  // the segment's parameter range inside this row
      if (b.y != a.y) {
        const float u = (float(r) - a.y) / (b.y - a.y), w = (float(r + 1) - a.y) / (b.y - a.y);
        t0 = std::max(0.0f, std::min(u, w));
        t1 = std::min(1.0f, std::max(u, w));
      }
      const float x0 = a.x + t0 * (b.x - a.x), x1 = a.x + t1 * (b.x - a.x);
      // One cell of margin each side: rounding at the row's edges never drops a cell.
      const int c0 = std::clamp(int(std::floor(std::min(x0, x1))) - 1, 0, columns_ - 1);
      const int c1 = std::clamp(int(std::floor(std::max(x0, x1))) + 1, 0, columns_ - 1);
      for (int c = c0; c <= c1; ++c) visit(r * columns_ + c);
    }
  }

  glm::vec2 origin_{0.0f};
  float cell_ = 1.0f;
  int columns_ = 1, rows_ = 1;
  std::vector<uint32_t> starts_, items_;
};

bool finite(glm::vec2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

}  // namespace

WallViolations countWallViolations(const WallGrid& walls, std::span<const glm::vec4> previous,
                                   std::span<const glm::vec4> placement, float minDistance) {
  WallViolations v;
  if (walls.segments.empty()) return v;
  const SegmentBins bins(walls.segments);
  std::vector<size_t> seenBy(walls.segments.size(), SIZE_MAX);  // a segment once per agent
  for (size_t i = 0; i < placement.size(); ++i) {
    const glm::vec2 p(placement[i].x, placement[i].z), q(previous[i].x, previous[i].z);
    bool crossed = false, close = false;
    auto check = [&](uint32_t k) {
      if (seenBy[k] == i) return;
      seenBy[k] = i;
      const Segment& s = walls.segments[k];
      const float d = glm::length(p - closestOnSegment(p, s.a, s.b));
      v.closest = std::min(v.closest, d);
      close = close || d < minDistance;
      crossed = crossed || (p != q && segmentsMeet(q, p, s.a, s.b));
    };
    // Exact with the bins: a segment farther than both the closest distance seen so far and
    // minDistance changes neither count nor minimum, and one the move crosses lies in its box.
    const float margin = std::max(minDistance, v.closest);
    if (finite(p) && finite(q) && margin < kNoWallHit) {
      bins.forEachNear(glm::min(p, q) - margin, glm::max(p, q) + margin, check);
    } else {
      for (uint32_t k = 0; k < walls.segments.size(); ++k) check(k);
    }
    v.crossings += crossed;
    v.tooClose += close;
  }
  return v;
}

}  // namespace throng::crowd
