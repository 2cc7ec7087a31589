#include "secondary/offline/cloth_sim.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <map>

#include "core/error.h"
#include "core/math.h"
#include "secondary/offline/primary_graph.h"

namespace throng::secondary {

class ClothModel {
 public:
  struct Constraint {
    uint32_t i, j;
    float rest;
    float compliance;
    // Fixed by the substep length: α̃ = compliance / h², the inverse masses and
    // 1 / (w_i + w_j + α̃), so the inner loop does one square root and one division.
    float alpha, wi, wj, inverseDenominator;
  };
  struct Attachment {
    uint32_t vertex, pin;
    float maxDistance;
  };
  std::shared_ptr<const PrimaryGraph> graph;
  std::shared_ptr<const ClothMesh> mesh;
  ClothSimOptions options;
  uint32_t vertexCount = 0, pinCount = 0, capsuleCount = 0;
  std::vector<float> invMass;           // 0 for pinned vertices
  std::vector<Constraint> constraints;  // ordered from the pins outwards
  std::vector<Attachment> attachments;
  std::vector<glm::vec3> pinTargets;   // nodes × pinned vertices
  std::vector<CapsuleShape> capsules;  // nodes × capsules
};

namespace {

glm::vec4 conjugate(glm::vec4 q) {
  return glm::vec4(-q.x, -q.y, -q.z, q.w);
}

void checkMesh(const ClothMesh& mesh, const PrimaryGraph& graph) {
  const uint32_t n = mesh.vertexCount();
  if (n == 0) fail("cloth mesh has no vertices");
  if (mesh.triangles.size() % 3 != 0)
    fail("cloth mesh: ", mesh.triangles.size(), " triangle indices, not triples");
  for (uint32_t v : mesh.triangles)
    if (v >= n) fail("cloth mesh: triangle index ", v, " of ", n, " vertices");
  if (mesh.pinJoints.size() != mesh.pinnedVertices.size() ||
      (!mesh.pinOffsets.empty() && mesh.pinOffsets.size() != mesh.pinnedVertices.size()))
    fail("cloth mesh: ", mesh.pinnedVertices.size(), " pinned vertices but ", mesh.pinJoints.size(),
         " pin joints and ", mesh.pinOffsets.size(), " pin offsets");
  for (size_t k = 0; k < mesh.pinnedVertices.size(); ++k) {
    if (mesh.pinnedVertices[k] >= n)
      fail("cloth mesh: pinned vertex ", mesh.pinnedVertices[k], " of ", n);
    if (mesh.pinJoints[k] >= graph.jointCount)
      fail("cloth mesh: pin joint ", mesh.pinJoints[k], " of a skeleton with ", graph.jointCount,
           " joints");
  }
}

std::vector<glm::vec3> pinOffsets(const ClothMesh& mesh, const PrimaryGraph& graph) {
  if (!mesh.pinOffsets.empty()) return mesh.pinOffsets;
  std::vector<glm::vec3> out;
  const NodeJoint* pose = graph.pose(0);
  for (size_t k = 0; k < mesh.pinnedVertices.size(); ++k) {
    const NodeJoint& joint = pose[mesh.pinJoints[k]];
    out.push_back(quatRotate(conjugate(joint.rotation),
                             mesh.restPositions[mesh.pinnedVertices[k]] - joint.position));
  }
  return out;
}

std::vector<glm::vec3> pinTargetsAt(const ClothMesh& mesh, const std::vector<glm::vec3>& offsets,
                                    const PrimaryGraph& graph, uint32_t node) {
  const NodeJoint* pose = graph.pose(node);
  std::vector<glm::vec3> out;
  for (size_t k = 0; k < offsets.size(); ++k) {
    const NodeJoint& joint = pose[mesh.pinJoints[k]];
    out.push_back(joint.position + quatRotate(joint.rotation, offsets[k]));
  }
  return out;
}

// Hop distance of every vertex from the pinned set along mesh edges (unreached: max).
std::vector<uint32_t> depthFromPins(const ClothMesh& mesh,
                                    const std::vector<std::vector<uint32_t>>& neighbours) {
  std::vector<uint32_t> depth(mesh.vertexCount(), std::numeric_limits<uint32_t>::max());
  std::deque<uint32_t> queue;
  for (uint32_t v : mesh.pinnedVertices) {
    depth[v] = 0;
    queue.push_back(v);
  }
  while (!queue.empty()) {
    const uint32_t v = queue.front();
    queue.pop_front();
    for (uint32_t w : neighbours[v])
      if (depth[w] == std::numeric_limits<uint32_t>::max()) {
        depth[w] = depth[v] + 1;
        queue.push_back(w);
      }
  }
  return depth;
}

void buildConstraints(ClothModel& model) {
  const ClothMesh& mesh = *model.mesh;
  const std::vector<glm::vec3>& rest = mesh.restPositions;
  // Edge → the vertices opposite it in its (one or two) triangles.
  std::map<std::pair<uint32_t, uint32_t>, std::vector<uint32_t>> edges;
  for (size_t t = 0; t < mesh.triangles.size(); t += 3)
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = mesh.triangles[t + e], b = mesh.triangles[t + (e + 1) % 3],
                     c = mesh.triangles[t + (e + 2) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back(c);
    }
  std::vector<std::vector<uint32_t>> neighbours(model.vertexCount);
  for (const auto& [edge, opposite] : edges) {
    neighbours[edge.first].push_back(edge.second);
    neighbours[edge.second].push_back(edge.first);
  }
  auto add = [&](uint32_t i, uint32_t j, float compliance) {
    if (model.invMass[i] + model.invMass[j] == 0.0f) return;  // both pinned: nothing to solve
    model.constraints.push_back(
        {i, j, glm::length(rest[i] - rest[j]), compliance, 0.0f, 0.0f, 0.0f, 0.0f});
  };
  for (const auto& [edge, opposite] : edges)
    add(edge.first, edge.second, model.options.stretchCompliance);
  for (const auto& [edge, opposite] : edges)
    if (opposite.size() == 2) add(opposite[0], opposite[1], model.options.bendCompliance);
  // Gauss–Seidel from the pins outwards: one sweep carries a pin's pull all the way down.
  const std::vector<uint32_t> depth = depthFromPins(mesh, neighbours);
  std::stable_sort(model.constraints.begin(), model.constraints.end(),
                   [&](const ClothModel::Constraint& a, const ClothModel::Constraint& b) {
                     return std::min(depth[a.i], depth[a.j]) < std::min(depth[b.i], depth[b.j]);
                   });
  if (model.options.longRangeAttachments && !mesh.pinnedVertices.empty())
    for (uint32_t v = 0; v < model.vertexCount; ++v) {
      if (model.invMass[v] == 0.0f) continue;
      uint32_t best = mesh.pinnedVertices.front();
      for (uint32_t p : mesh.pinnedVertices)
        if (glm::length(rest[v] - rest[p]) < glm::length(rest[v] - rest[best])) best = p;
      model.attachments.push_back(
          {v, best, model.options.attachmentSlack * glm::length(rest[v] - rest[best])});
    }
}

struct Box {
  glm::vec3 lo, hi;
};

// One Gauss–Seidel sweep of XPBD distance constraints (Macklin et al. 2016, eq. 18).
template <bool kAccumulated>
void solveDistances(const std::vector<ClothModel::Constraint>& constraints,
                    std::vector<glm::vec3>& x, std::vector<float>& lambda) {
  for (size_t c = 0; c < constraints.size(); ++c) {
    const ClothModel::Constraint& con = constraints[c];
    const glm::vec3 d = x[con.i] - x[con.j];
    const float len = std::sqrt(glm::dot(d, d));
    if (len < 1e-9f) continue;
    const float previous = kAccumulated ? lambda[c] : 0.0f;
    const float dLambda = (con.rest - len - con.alpha * previous) * con.inverseDenominator;
    lambda[c] = previous + dLambda;
    const glm::vec3 g = d * (dLambda / len);
    x[con.i] += con.wi * g;
    x[con.j] -= con.wj * g;
  }
}

void projectOut(glm::vec3& p, const CapsuleShape& c, float radius) {
  const glm::vec3 ab = c.b - c.a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - c.a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  const glm::vec3 q = c.a + t * ab;
  const glm::vec3 d = p - q;
  const float dist2 = glm::dot(d, d);
  if (dist2 >= radius * radius) return;
  const float dist = std::sqrt(dist2);
  // A vertex on the axis itself goes out backwards, where the cloth hangs.
  p = dist > 1e-9f ? q + d * (radius / dist) : q + glm::vec3(0.0f, 0.0f, -radius);
}

}  // namespace

void validateClothSimOptions(const ClothSimOptions& o) {
  if (o.substeps == 0 || o.substeps > 1000)
    fail("cloth: substeps must be in [1, 1000], got ", o.substeps);
  if (o.iterations == 0 || o.iterations > 100)
    fail("cloth: iterations must be in [1, 100], got ", o.iterations);
  if (o.drag < 0.0f || o.internalDamping < 0.0f || !(o.areaDensity > 0.0f) ||
      o.stretchCompliance < 0.0f || o.bendCompliance < 0.0f || o.thickness < 0.0f ||
      o.attachmentSlack < 1.0f)
    fail(
        "cloth: drag, internal damping, compliances and thickness must be ≥ 0, density > 0 and "
        "attachment slack ≥ 1");
}

std::vector<float> vertexMasses(const ClothMesh& mesh, float areaDensity) {
  std::vector<float> mass(mesh.vertexCount(), 0.0f);
  const std::vector<glm::vec3>& p = mesh.restPositions;
  for (size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
    const uint32_t a = mesh.triangles[t], b = mesh.triangles[t + 1], c = mesh.triangles[t + 2];
    const float third =
        areaDensity * 0.5f * glm::length(glm::cross(p[b] - p[a], p[c] - p[a])) / 3.0f;
    mass[a] += third;
    mass[b] += third;
    mass[c] += third;
  }
  return mass;
}

std::shared_ptr<const ClothModel> makeClothModel(std::shared_ptr<const PrimaryGraph> graph,
                                                 std::shared_ptr<const ClothMesh> mesh,
                                                 const ClothSimOptions& options) {
  THRONG_CHECK(graph && mesh, "cloth model needs a graph and a mesh");
  validateClothSimOptions(options);
  validatePrimaryGraph(*graph);
  checkMesh(*mesh, *graph);
  auto model = std::make_shared<ClothModel>();
  model->graph = graph;
  model->mesh = mesh;
  model->options = options;
  model->vertexCount = mesh->vertexCount();
  model->pinCount = uint32_t(mesh->pinnedVertices.size());
  const std::vector<float> mass = vertexMasses(*mesh, options.areaDensity);
  float smallest = std::numeric_limits<float>::max();
  for (float m : mass)
    if (m > 0.0f) smallest = std::min(smallest, m);
  for (float m : mass) model->invMass.push_back(1.0f / (m > 0.0f ? m : smallest));
  for (uint32_t v : mesh->pinnedVertices) model->invMass[v] = 0.0f;
  buildConstraints(*model);
  const float h = graph->frameTime / float(options.substeps);
  for (ClothModel::Constraint& c : model->constraints) {
    c.alpha = c.compliance / (h * h);
    c.wi = model->invMass[c.i];
    c.wj = model->invMass[c.j];
    c.inverseDenominator = 1.0f / (c.wi + c.wj + c.alpha);
  }

  const std::vector<glm::vec3> offsets = pinOffsets(*mesh, *graph);
  const std::vector<Capsule> capsules = resolveCapsules(*graph, options.capsules);
  model->capsuleCount = uint32_t(capsules.size());
  for (uint32_t n = 0; n < graph->nodes.size(); ++n) {
    const std::vector<glm::vec3> pins = pinTargetsAt(*mesh, offsets, *graph, n);
    model->pinTargets.insert(model->pinTargets.end(), pins.begin(), pins.end());
    const std::vector<CapsuleShape> shapes = capsulesAt(*graph, capsules, n);
    model->capsules.insert(model->capsules.end(), shapes.begin(), shapes.end());
  }
  return model;
}

ClothState stepCloth(const ClothModel& model, const ClothState& from, uint32_t fromNode,
                     uint32_t toNode) {
  const PrimaryGraph& graph = *model.graph;
  const ClothSimOptions& o = model.options;
  const uint32_t n = model.vertexCount;
  if (from.positions.size() != n || from.velocities.size() != n)
    fail("cloth step: state has ", from.positions.size(), " positions and ", from.velocities.size(),
         " velocities for a mesh of ", n, " vertices");
  const glm::vec3 shift = graph.rootStep.at(fromNode)[edgeIndex(graph, fromNode, toNode)];
  const uint32_t pins = model.pinCount, caps = model.capsuleCount;
  const glm::vec3* pins0 = model.pinTargets.data() + size_t(fromNode) * pins;
  const glm::vec3* pins1 = model.pinTargets.data() + size_t(toNode) * pins;
  const CapsuleShape* caps0 = model.capsules.data() + size_t(fromNode) * caps;
  const CapsuleShape* caps1 = model.capsules.data() + size_t(toNode) * caps;
  const std::vector<uint32_t>& pinned = model.mesh->pinnedVertices;

  ClothState out{from.positions, from.velocities};
  std::vector<glm::vec3>& x = out.positions;
  std::vector<glm::vec3>& v = out.velocities;
  std::vector<glm::vec3> previous(n);
  std::vector<float> lambda(model.constraints.size());
  std::vector<CapsuleShape> shapes(caps);
  std::vector<Box> boxes(caps);
  const float h = graph.frameTime / float(o.substeps);
  const float dragFactor = std::exp(-o.drag * h);
  const float radiusPad = o.thickness;
  const float internalFraction = 1.0f - std::exp(-o.internalDamping * h);

  for (uint32_t sub = 1; sub <= o.substeps; ++sub) {
    const float t = float(sub) / float(o.substeps);
    for (uint32_t c = 0; c < caps; ++c) {
      shapes[c] = {glm::mix(caps0[c].a, caps1[c].a + shift, t),
                   glm::mix(caps0[c].b, caps1[c].b + shift, t), caps0[c].radius + radiusPad};
      const glm::vec3 r(shapes[c].radius);
      boxes[c] = {glm::min(shapes[c].a, shapes[c].b) - r, glm::max(shapes[c].a, shapes[c].b) + r};
    }
    for (uint32_t i = 0; i < n; ++i) {
      previous[i] = x[i];
      if (model.invMass[i] == 0.0f) continue;
      v[i] = (v[i] + o.gravity * h) * dragFactor;
      x[i] += v[i] * h;
    }
    for (uint32_t k = 0; k < pins; ++k) x[pinned[k]] = glm::mix(pins0[k], pins1[k] + shift, t);

    std::fill(lambda.begin(), lambda.end(), 0.0f);
    for (uint32_t iteration = 0; iteration < o.iterations; ++iteration) {
      if (iteration == 0)
        solveDistances<false>(model.constraints, x, lambda);  // λ starts at 0
      else
        solveDistances<true>(model.constraints, x, lambda);
      for (const ClothModel::Attachment& a : model.attachments) {
        const glm::vec3 d = x[a.vertex] - x[a.pin];
        const float len2 = glm::dot(d, d);
        if (len2 > a.maxDistance * a.maxDistance)
          x[a.vertex] = x[a.pin] + d * (a.maxDistance / std::sqrt(len2));
      }
    }

    for (uint32_t i = 0; i < n; ++i) {
      if (model.invMass[i] == 0.0f) continue;
      glm::vec3 p = x[i];
      bool hit = false;
      for (uint32_t c = 0; c < caps; ++c) {
        if (glm::any(glm::lessThan(p, boxes[c].lo)) || glm::any(glm::greaterThan(p, boxes[c].hi)))
          continue;
        const glm::vec3 before = p;
        projectOut(p, shapes[c], shapes[c].radius);
        hit = hit || p != before;
      }
      // Pushed out of one capsule into an overlapping one: one more pass settles joints.
      if (hit)
        for (uint32_t c = 0; c < caps; ++c)
          if (!glm::any(glm::lessThan(p, boxes[c].lo)) &&
              !glm::any(glm::greaterThan(p, boxes[c].hi)))
            projectOut(p, shapes[c], shapes[c].radius);
      if (o.ground) p.y = std::max(p.y, o.groundHeight + o.thickness);
      x[i] = p;
    }
    const float inverseStep = 1.0f / h;
    for (uint32_t i = 0; i < n; ++i)
      if (model.invMass[i] != 0.0f) v[i] = (x[i] - previous[i]) * inverseStep;
    // Internal damping: every constraint's pair of vertices loses that share of its relative
    // velocity (momentum-conserving, Gauss–Seidel from the pins outwards), so flutter dies out
    // while the motion of the cape as a whole, and its drag against the air, stay.
    if (internalFraction > 0.0f)
      for (const ClothModel::Constraint& con : model.constraints) {
        const glm::vec3 dv = (v[con.j] - v[con.i]) * (internalFraction / (con.wi + con.wj));
        v[con.i] += con.wi * dv;
        v[con.j] -= con.wj * dv;
      }
  }
  for (uint32_t k = 0; k < pins; ++k)
    v[pinned[k]] = (pins1[k] + shift - pins0[k]) / graph.frameTime;
  for (glm::vec3& p : x) p -= shift;
  return out;
}

StepFunction makeClothStepFunction(std::shared_ptr<const PrimaryGraph> graph,
                                   std::shared_ptr<const ClothMesh> mesh,
                                   const ClothSimOptions& options) {
  std::shared_ptr<const ClothModel> model =
      makeClothModel(std::move(graph), std::move(mesh), options);
  return [model](const ClothState& from, uint32_t fromNode, uint32_t toNode) {
    return stepCloth(*model, from, fromNode, toNode);
  };
}

ClothState restState(const ClothMesh& mesh, const PrimaryGraph& graph, uint32_t node) {
  validatePrimaryGraph(graph);
  checkMesh(mesh, graph);
  if (node >= graph.nodes.size()) fail("cloth rest state: node ", node, " of ", graph.nodes.size());
  const std::vector<glm::vec3> targets = pinTargetsAt(mesh, pinOffsets(mesh, graph), graph, node);
  glm::vec3 shift(0.0f);
  for (size_t k = 0; k < targets.size(); ++k)
    shift += (targets[k] - mesh.restPositions[mesh.pinnedVertices[k]]) / float(targets.size());
  ClothState state;
  for (const glm::vec3& p : mesh.restPositions) state.positions.push_back(p + shift);
  for (size_t k = 0; k < targets.size(); ++k) state.positions[mesh.pinnedVertices[k]] = targets[k];
  const uint32_t next = naturalSuccessor(graph, node);
  const glm::vec3 velocity = graph.rootStep[node][edgeIndex(graph, node, next)] / graph.frameTime;
  state.velocities.assign(mesh.vertexCount(), velocity);
  return state;
}

ClothState settleCloth(const StepFunction& step, const PrimaryGraph& graph, ClothState state,
                       uint32_t node, uint32_t minFrames) {
  uint32_t at = node;
  const uint64_t limit = uint64_t(minFrames) + graph.nodes.size() + 1;
  for (uint64_t frames = 0; frames < minFrames || at != node; ++frames) {
    if (frames > limit)
      fail("cloth settle: the natural walk from node ", node, " never returns to it");
    const uint32_t next = naturalSuccessor(graph, at);
    state = step(state, at, next);
    at = next;
  }
  return state;
}

}  // namespace throng::secondary
