#pragma once
// Static obstacles of the crowd: line segments in the ground plane (x, z), from open polylines,
// closed polygons or the boundary of a walkable-area raster, so one mechanism handles all three.
// Segments never move, so they are binned once on the CPU into a uniform grid of their own
// (WallGrid, compressed rows: per cell a start and a count into one index list) that the
// steering pass and the wall constraint read (avoidance_jobs.h, shaders/avoidance_walls.glsl).
// This file also holds the CPU twins of the wall math: the time a moving disc first touches a
// segment, the wall terms of both policies and the constraint that keeps agents off the walls.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace throng::crowd {

struct Segment {
  glm::vec2 a{0.0f}, b{0.0f};  // ground plane (x, z), metres
};

inline constexpr size_t kMaxSegments = 1000000;
// Coordinates beyond this are refused: float positions lose the millimetres the constraint keeps.
inline constexpr float kMaxWallCoordinate = 1.0e5f;
inline constexpr float kMinSegmentLength = 1.0e-4f;  // shorter segments are degenerate (m)
// Budget of (cell, segment) pairs of the binning (the GPU keeps a 16-byte copy of the segment per
// pair: 256 MiB at most) and of the grid's cells.
inline constexpr size_t kMaxWallEntries = size_t(16) << 20;
inline constexpr size_t kMaxWallCells = size_t(16) << 20;
// The constraint keeps agents this much farther than their radius from a wall, so rounding never
// leaves a sliding agent just inside it (which would pin it to the wall).
inline constexpr float kWallSkin = 1.0e-4f;

// A raster of walkable cells: cell (c, r) covers origin + [c, c+1) × [r, r+1) · cellSize.
struct WalkableGrid {
  glm::vec2 origin{0.0f};
  float cellSize = 1.0f;
  uint32_t columns = 0, rows = 0;
  std::vector<uint8_t> walkable;  // rows × columns, row-major, non-zero: walkable
};

struct Obstacles {
  std::vector<Segment> segments;

  // Consecutive points joined; `closed` also joins the last to the first (a polygon). Throws
  // Error for fewer than 2 points (3 for a polygon).
  void addPolyline(std::span<const glm::vec2> points, bool closed);
  // The edges between walkable and blocked cells (outside the raster counts as blocked), merged
  // into straight runs so a long wall is one segment. Throws Error for an inconsistent raster.
  void addWalkableGrid(const WalkableGrid& grid);
  bool empty() const { return segments.empty(); }
};
// Problems with the segments (empty when valid): count, finite and bounded coordinates, length.
std::vector<std::string> validateObstacles(const Obstacles& obstacles);

// The binned segments. Cell (c, r) covers origin + [c, c+1) × [r, r+1) · cellSize and lists
// every segment that comes within `reach` of it, so an agent finds all segments within reach
// in its own cell; points outside the grid are farther than reach from every segment.
struct WallGrid {
  glm::vec2 origin{0.0f};
  float cellSize = 1.0f;
  float reach = 0.0f;
  uint32_t columns = 0, rows = 0;
  std::vector<Segment> segments;
  std::vector<uint32_t> starts;   // per cell + 1: first entry of its list (prefix sums)
  std::vector<uint32_t> indices;  // segment indices, by cell
  // Per cell: its distance to the nearest listed segment (reach where none is listed), so the
  // constraint skips a cell's list when its move cannot come that close.
  std::vector<float> clearance;
  uint32_t cellOf(glm::vec2 p) const;  // UINT32_MAX outside the grid
};
// Throws Error for invalid obstacles, a non-positive cell size or reach, or a binning that would
// need more than `maxEntries` entries or kMaxWallCells cells.
WallGrid binObstacles(const Obstacles& obstacles, float cellSize, float reach,
                      size_t maxEntries = kMaxWallEntries);

// The wall math, mirrored by shaders/avoidance_walls.glsl.
glm::vec2 closestOnSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b);
inline constexpr float kNoWallHit = 1.0e30f;
// The first t >= 0 at which a disc of radius r at p moving by m per unit of t touches segment ab,
// with the contact normal (unit, from the wall towards the disc; zero for a disc centred on the
// segment). A disc already closer than r: t = 0 when it moves closer, else no hit (kNoWallHit).
float segmentHit(glm::vec2 p, glm::vec2 m, glm::vec2 a, glm::vec2 b, float r, glm::vec2& normal);
// Where an agent moving from `from` to `to` ends: the first contact with a wall (kept at
// radius + kWallSkin), then the rest of the move projected onto the wall's tangent, up to three
// contacts; a move longer than reach − radius is shortened to that (the grid's lists hold
// segments within reach only).
glm::vec2 constrainMove(const WallGrid& walls, glm::vec2 from, glm::vec2 to, float radius);
// The twin of WallConstraintJob: placement[i].xz of agents [first, first + count) constrained
// from previous[i].xz.
void wallConstraintCpu(const WallGrid& walls, float radius, std::span<const glm::vec4> previous,
                       std::span<glm::vec4> placement, uint32_t first, uint32_t count);

// Checks of the hard guarantee: moves whose path crossed a segment, and agents closer than
// `minDistance` to one. Exact over walls.segments, which the check bins by itself: the grid's
// lists are part of what it checks.
struct WallViolations {
  size_t crossings = 0, tooClose = 0;
  float closest = kNoWallHit;  // smallest distance of an agent to a segment seen
};
WallViolations countWallViolations(const WallGrid& walls, std::span<const glm::vec4> previous,
                                   std::span<const glm::vec4> placement, float minDistance);

}  // namespace throng::crowd
