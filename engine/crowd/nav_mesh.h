#pragma once
// Path planning on the CPU (docs/design.md, "Goals and navigation"): a navigation mesh of convex
// polygons with adjacency, searched by A* over polygons and turned into waypoints by the funnel
// (string pulling); a road map (a graph of way points) searched by A*; a straight line when
// neither is given. Plans are made when an agent's goal changes (goals.h), not per frame; the
// GPU follows the waypoints (nav_jobs.h).
//
// The structs are Throng's own, not Menge's: engine/crowd keeps its own layout (oriented
// polygons, adjacency per edge, a lookup grid) whatever the source; navMeshFromMenge and
// roadMapFromMenge convert engine/menge's plain data, Menge (x, y) becoming (x, z).
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "crowd/obstacles.h"

namespace throng::menge {
struct NavMesh;
struct RoadMap;
}  // namespace throng::menge

namespace throng::crowd {

struct NavPolygon {
  std::vector<uint32_t> vertices;  // counter-clockwise in (x, z) taken as (x, y)
  std::vector<int32_t> neighbors;  // per edge vertices[k] → vertices[k + 1]: polygon or -1 (wall)
  glm::vec2 lo{0.0f}, hi{0.0f};    // bounds
};

struct NavMesh {
  std::vector<glm::vec2> vertices;
  std::vector<NavPolygon> polygons;
  // Lookup grid over the bounds: per cell the polygons whose bounds overlap it.
  glm::vec2 gridOrigin{0.0f};
  float gridCell = 1.0f;
  glm::ivec2 gridSize{0};
  std::vector<uint32_t> cellStart;  // per cell + 1, into cellPolygons
  std::vector<uint32_t> cellPolygons;

  bool empty() const { return polygons.empty(); }
};

// Builds a mesh from polygons given as vertex indices (either winding; made counter-clockwise).
// Adjacency: two polygons sharing an edge (the same two vertex indices) are neighbours. Throws
// Error for an index out of range, a polygon of fewer than 3 vertices or no area, one that is not
// convex, or an edge shared by more than two polygons.
NavMesh makeNavMesh(std::vector<glm::vec2> vertices,
                    const std::vector<std::vector<uint32_t>>& polygons);
NavMesh navMeshFromMenge(const menge::NavMesh& mesh);

// The polygon containing p (within `tolerance` metres of its edges), or -1.
int findPolygon(const NavMesh& mesh, glm::vec2 p, float tolerance = 1e-4f);
// The point of the mesh closest to p and its polygon (p itself when inside).
glm::vec2 closestMeshPoint(const NavMesh& mesh, glm::vec2 p, int* polygon = nullptr);

struct RoadMap {
  std::vector<glm::vec2> points;
  std::vector<std::vector<uint32_t>> neighbors;  // per point (undirected edges, both ways)
  // The walls of the scene, for the visibility tests of planOnRoadMap; empty: everything is
  // taken as visible.
  std::vector<Segment> walls;

  bool empty() const { return points.empty(); }
};
// Throws Error for an edge naming a point that does not exist.
RoadMap makeRoadMap(std::vector<glm::vec2> points,
                    const std::vector<std::pair<uint32_t, uint32_t>>& edges);
RoadMap roadMapFromMenge(const menge::RoadMap& map);

// A planned path: `points` start with the start and end with the point reached.
struct PlannedPath {
  std::vector<glm::vec2> points;
  std::vector<uint32_t> corridor;  // nav mesh: the polygons crossed, start to end
  // The documented fallbacks: a start or target off the mesh is moved to the closest point of the
  // mesh; a target the start cannot reach (another part of the mesh, or of the road map) is
  // replaced by the closest point to it the start can reach. Either sets `partial`.
  bool partial = false;
};

// A* over polygons (cost: distance between portal midpoints), then the funnel. With a
// `clearance`, each corner is moved that far off the wall vertex it turns around (where the
// moved point is still on the mesh), so a crowd does not converge on the vertex itself.
PlannedPath planOnNavMesh(const NavMesh& mesh, glm::vec2 start, glm::vec2 target,
                          float clearance = 0.0f);
// A* over the road map: start → nearest way point → … → way point nearest the target → target.
// With the map's walls (as Menge's road maps): a target visible from the start (no wall crosses
// the line) is walked to straight, and the way points entered and left are the nearest visible
// from the start and from the target (the nearest ones when none is). Without walls the nearest
// way points are taken as visible. A target at the start is a path of two equal points (an
// agent told to stay where it is does not walk out to the road map).
PlannedPath planOnRoadMap(const RoadMap& map, glm::vec2 start, glm::vec2 target);
// Whether the segments p–q and a–b cross or touch (running along the same line is not crossing).
bool segmentsCross(glm::vec2 p, glm::vec2 q, glm::vec2 a, glm::vec2 b);
// Whether the straight line from p to q crosses none of `walls` (touching counts as crossing).
bool visible(std::span<const Segment> walls, glm::vec2 p, glm::vec2 q);
// The nav mesh if there is one, else the road map, else the straight line.
PlannedPath planPath(const NavMesh& mesh, const RoadMap& map, glm::vec2 start, glm::vec2 target,
                     float clearance = 0.0f);

// Whether the straight line from p to q stays on the mesh (p and q on it, no wall edge crossed).
bool visibleOnMesh(const NavMesh& mesh, glm::vec2 p, glm::vec2 q);

// What is left of `path` to an agent at p: the way to the path's nearest point, then along the
// path to its end. It shrinks as the agent follows the path, wherever the path turns.
float remainingPathLength(std::span<const glm::vec2> path, glm::vec2 p);

// String pulling through portals (left, right as seen walking from start to target): the corners
// of the shortest path inside the corridor, start first and target last.
std::vector<glm::vec2> funnelPath(glm::vec2 start, glm::vec2 target,
                                  const std::vector<std::pair<glm::vec2, glm::vec2>>& portals);

}  // namespace throng::crowd
