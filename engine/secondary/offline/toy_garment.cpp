#include "secondary/offline/toy_garment.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace throng::secondary {
namespace {
constexpr uint32_t kToyCycles[2] = {8, 6};
constexpr float kToySpeed[2] = {1.5f, 3.5f};   // m/s
constexpr float kToySway[2] = {0.04f, 0.10f};  // neck sway amplitude, m
constexpr glm::vec3 kChestCentre{0.0f, 1.28f, 0.02f};
constexpr float kChestRadius = 0.14f;
constexpr float kTwoPi = 6.28318530718f;

uint32_t toyNode(uint32_t bucket, uint32_t frame) {
  return bucket == 0 ? frame : kToyCycles[0] + frame;
}

glm::vec3 neckAt(const PrimaryGraph& g, uint32_t node) {
  return g.pose(node)[1].position;
}
}  // namespace

PrimaryGraph makeToyPrimaryGraph() {
  PrimaryGraph g;
  g.frameTime = 1.0f / 30.0f;
  g.jointCount = 2;
  g.parents = {-1, 0};
  g.jointNames = {"Hips", "Neck"};
  for (uint32_t b = 0; b < 2; ++b) {
    for (uint32_t f = 0; f < kToyCycles[b]; ++f) {
      const float phase = float(f) / float(kToyCycles[b]);
      g.nodes.push_back({0, b, f});
      g.poses.push_back(
          {{0.0f, 1.0f + 0.02f * std::cos(2.0f * kTwoPi * phase), 0.0f}, {0, 0, 0, 1}});
      g.poses.push_back({{kToySway[b] * std::sin(kTwoPi * phase),
                          1.5f + 0.03f * std::cos(2.0f * kTwoPi * phase), 0.04f * float(b)},
                         {0, 0, 0, 1}});
      const glm::vec3 step{0.0f, 0.0f, kToySpeed[b] * g.frameTime};
      if (f + 1 < kToyCycles[b]) {
        g.successors.push_back({toyNode(b, f + 1)});
        g.rootStep.push_back({step});
      } else {
        g.successors.push_back({toyNode(0, 0), toyNode(1, 0)});
        g.rootStep.push_back({step, step});
      }
    }
  }
  return g;
}

ClothMesh makeToyChain(const PrimaryGraph& graph, const ToyGarmentOptions& options) {
  if (options.links == 0 || !(options.linkLength > 0.0f))
    fail("toy garment: links and link length must be positive");
  ClothMesh mesh;
  const glm::vec3 neck = neckAt(graph, 0);
  for (uint32_t i = 0; i <= options.links; ++i)
    mesh.restPositions.push_back(
        neck + glm::vec3(0.0f, -options.linkLength * float(i), -0.02f * float(i)));
  mesh.pinnedVertices = {0};
  mesh.pinJoints = {1};
  mesh.pinOffsets = {glm::vec3(0.0f)};
  return mesh;
}

ClothState toyRestState(const ClothMesh& mesh, const PrimaryGraph& graph, uint32_t node) {
  ClothState s;
  const glm::vec3 shift = neckAt(graph, node) - mesh.restPositions[0];
  const glm::vec3 velocity = graph.rootStep[node][0] / graph.frameTime;
  for (const glm::vec3& p : mesh.restPositions) {
    s.positions.push_back(p + shift);
    s.velocities.push_back(velocity);
  }
  return s;
}

StepFunction makeToyStepFunction(std::shared_ptr<const PrimaryGraph> graph,
                                 std::shared_ptr<const ClothMesh> mesh,
                                 const ToyGarmentOptions& options) {
  if (options.substeps == 0) fail("toy garment: substeps must be positive");
  const float link = options.linkLength;
  return [graph, mesh, options, link](const ClothState& from, uint32_t fromNode, uint32_t toNode) {
    const PrimaryGraph& g = *graph;
    const std::vector<uint32_t>& next = g.successors.at(fromNode);
    const auto it = std::find(next.begin(), next.end(), toNode);
    if (it == next.end()) fail("toy garment: ", fromNode, " → ", toNode, " is not a primary edge");
    const glm::vec3 rootStep = g.rootStep[fromNode][size_t(it - next.begin())];
    const size_t n = from.positions.size();
    if (n != mesh->vertexCount() || from.velocities.size() != n)
      fail("toy garment: state does not fit the chain");

    // Simulated in fromNode's character space; the pin goes to toNode's neck moved by the root
    // step.
    std::vector<glm::vec3> x = from.positions, v = from.velocities, prev(n);
    const glm::vec3 pinFrom = neckAt(g, fromNode), pinTo = neckAt(g, toNode) + rootStep;
    const float h = g.frameTime / float(options.substeps);
    const glm::vec3 gravity{0.0f, -9.81f, 0.0f};
    for (uint32_t s = 1; s <= options.substeps; ++s) {
      prev = x;
      const float a = float(s) / float(options.substeps);
      const glm::vec3 pin = glm::mix(pinFrom, pinTo, a);
      for (size_t i = 1; i < n; ++i) {
        v[i] += h * (gravity - options.drag * v[i]);
        x[i] += h * v[i];
      }
      x[0] = pin;
      for (size_t i = 1; i < n; ++i) {
        const glm::vec3 d = x[i] - x[i - 1];
        const float len = glm::length(d);
        if (len > 1e-6f) x[i] = x[i - 1] + d * (link / len);
        const glm::vec3 c = x[i] - (kChestCentre + a * rootStep);
        const float r = glm::length(c);
        if (r < kChestRadius && r > 1e-6f) x[i] += c * ((kChestRadius - r) / r);
      }
      for (size_t i = 0; i < n; ++i) v[i] = (x[i] - prev[i]) / h;
    }
    ClothState out;
    out.positions.resize(n);
    for (size_t i = 0; i < n; ++i) out.positions[i] = x[i] - rootStep;
    out.velocities = std::move(v);
    return out;
  };
}

}  // namespace throng::secondary
