#include "secondary/offline/cloth_mesh.h"

#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/math.h"
#include "secondary/offline/primary_graph.h"

namespace throng::secondary {
namespace {

glm::vec4 conjugate(glm::vec4 q) {
  return glm::vec4(-q.x, -q.y, -q.z, q.w);
}

struct Sample {
  glm::vec3 p;
  float radius;
};

// Points along every capsule axis, to test the tilted rest plane against.
std::vector<Sample> capsuleSamples(const std::vector<CapsuleShape>& shapes) {
  constexpr int kPerCapsule = 9;
  std::vector<Sample> out;
  for (const CapsuleShape& c : shapes)
    for (int k = 0; k < kPerCapsule; ++k)
      out.push_back({glm::mix(c.a, c.b, float(k) / (kPerCapsule - 1)), c.radius});
  return out;
}

// True when every sample under the cape lies in front of its plane by radius + clearance.
bool clears(const std::vector<Sample>& samples, glm::vec3 top, float angle, const CapeOptions& o) {
  const glm::vec3 down(0.0f, -std::cos(angle), -std::sin(angle));
  const glm::vec3 front(0.0f, -std::sin(angle), std::cos(angle));
  for (const Sample& s : samples) {
    const glm::vec3 d = s.p - top;
    const float along = glm::dot(d, down);
    if (along < -s.radius || along > o.length + s.radius) continue;
    const float half =
        0.5f * o.topWidth * (1.0f + (o.flare - 1.0f) * std::clamp(along / o.length, 0.0f, 1.0f));
    if (std::abs(d.x) > half + s.radius) continue;
    if (glm::dot(d, front) < s.radius + o.clearance) return false;
  }
  return true;
}

void checkOptions(const CapeOptions& o) {
  if (o.columns < 2 || o.rows < 2)
    fail("cape: need at least 2 × 2 vertices, got ", o.columns, " × ", o.rows);
  if (!(o.topWidth > 0.0f) || !(o.length > 0.0f) || !(o.flare > 0.0f) || o.clearance < 0.0f)
    fail("cape: width, length and flare must be > 0 and clearance ≥ 0");
}

}  // namespace

std::vector<uint32_t> gridTriangles(uint32_t rows, uint32_t columns) {
  std::vector<uint32_t> tris;
  for (uint32_t r = 0; r + 1 < rows; ++r)
    for (uint32_t c = 0; c + 1 < columns; ++c) {
      const uint32_t v00 = r * columns + c, v01 = v00 + 1, v10 = v00 + columns, v11 = v10 + 1;
      if ((r + c) % 2 == 0)
        tris.insert(tris.end(), {v00, v10, v11, v00, v11, v01});
      else
        tris.insert(tris.end(), {v00, v10, v01, v01, v10, v11});
    }
  return tris;
}

ClothMesh makeCape(const PrimaryGraph& graph, const CapeOptions& o) {
  checkOptions(o);
  validatePrimaryGraph(graph);
  if (o.node >= graph.nodes.size())
    fail("cape: node ", o.node, " of a graph with ", graph.nodes.size(), " nodes");
  const std::vector<uint32_t> anchors = neckShoulderJoints(graph);
  if (anchors.empty())
    fail("cape: the skeleton has no neck or shoulder joint to hang the cape from");
  const NodeJoint* pose = graph.pose(o.node);
  glm::vec3 centre(0.0f);
  float frontmost = std::numeric_limits<float>::max();
  for (uint32_t j : anchors) {
    centre += pose[j].position / float(anchors.size());
    frontmost = std::min(frontmost, pose[j].position.z);
  }
  const std::vector<Sample> samples =
      capsuleSamples(capsulesAt(graph, resolveCapsules(graph, o.capsules), o.node));
  // The least tilt back that clears the body; move the top row back until one exists.
  glm::vec3 top(centre.x, centre.y, frontmost - o.clearance);
  float angle = -1.0f;
  for (int back = 0; back <= 50 && angle < 0.0f; ++back) {
    top.z = frontmost - o.clearance - 0.01f * float(back);
    for (int degrees = 0; degrees <= 70 && angle < 0.0f; ++degrees)
      if (clears(samples, top, float(degrees) * kPi / 180.0f, o))
        angle = float(degrees) * kPi / 180.0f;
  }
  if (angle < 0.0f) fail("cape: found no rest shape clear of the body at node ", o.node);

  ClothMesh mesh;
  const glm::vec3 down(0.0f, -std::cos(angle), -std::sin(angle));
  for (uint32_t r = 0; r < o.rows; ++r) {
    const float s = o.length * float(r) / float(o.rows - 1);
    const float half = 0.5f * o.topWidth * (1.0f + (o.flare - 1.0f) * s / o.length);
    for (uint32_t c = 0; c < o.columns; ++c) {
      const float u = float(c) / float(o.columns - 1);
      mesh.restPositions.push_back(top + s * down +
                                   glm::vec3((2.0f * u - 1.0f) * half, 0.0f, 0.0f));
    }
  }
  mesh.triangles = gridTriangles(o.rows, o.columns);
  for (uint32_t c = 0; c < o.columns; ++c) {
    const glm::vec3 p = mesh.restPositions[c];
    uint32_t best = anchors.front();
    for (uint32_t j : anchors)
      if (glm::length(p - pose[j].position) < glm::length(p - pose[best].position)) best = j;
    mesh.pinnedVertices.push_back(c);
    mesh.pinJoints.push_back(best);
    mesh.pinOffsets.push_back(quatRotate(conjugate(pose[best].rotation), p - pose[best].position));
  }
  return mesh;
}

ClothMesh makeSquareCloth(uint32_t n, float size) {
  if (n < 2 || !(size > 0.0f))
    fail("square cloth: need n ≥ 2 and size > 0, got ", n, " and ", size);
  ClothMesh mesh;
  for (uint32_t r = 0; r < n; ++r)
    for (uint32_t c = 0; c < n; ++c)
      mesh.restPositions.push_back(
          glm::vec3(size * (float(c) / float(n - 1) - 0.5f), 0.0f, size * float(r) / float(n - 1)));
  mesh.triangles = gridTriangles(n, n);
  for (uint32_t c = 0; c < n; ++c) {
    mesh.pinnedVertices.push_back(c);
    mesh.pinJoints.push_back(0);
    mesh.pinOffsets.push_back(mesh.restPositions[c]);
  }
  return mesh;
}

}  // namespace throng::secondary
