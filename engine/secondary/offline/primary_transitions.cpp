// Other clips joining the primary graph: transitions where two poses and their joint velocities
// are close (Kovar et al.'s motion-graph criterion, on character-space joint positions).
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "secondary/offline/primary_graph.h"

namespace throng::secondary {
namespace {

// Joint positions and world velocities (heading 0) of one pose, the transition features.
struct Features {
  uint32_t joints = 0;
  std::vector<glm::vec3> position;  // items × joints
  std::vector<glm::vec3> velocity;
  const glm::vec3* p(uint32_t i) const { return position.data() + size_t(i) * joints; }
  const glm::vec3* v(uint32_t i) const { return velocity.data() + size_t(i) * joints; }
};

void appendFeature(Features& out, const NodeJoint* pose, const NodeJoint* next, glm::vec3 step,
                   float dt) {
  for (uint32_t j = 0; j < out.joints; ++j) {
    out.position.push_back(pose[j].position);
    out.velocity.push_back((next[j].position + step - pose[j].position) / dt);
  }
}

Features graphFeatures(const PrimaryGraph& graph) {
  Features f{graph.jointCount, {}, {}};
  for (uint32_t n = 0; n < graph.nodes.size(); ++n) {
    const uint32_t next = naturalSuccessor(graph, n);
    appendFeature(f, graph.pose(n), graph.pose(next), graph.rootStep[n][edgeIndex(graph, n, next)],
                  graph.frameTime);
  }
  return f;
}

Features clipFeatures(const ClipPoses& clip, float dt) {
  Features f{clip.jointCount, {}, {}};
  const uint32_t frames = clip.frameCount();
  auto pose = [&](uint32_t c) { return clip.poses.data() + size_t(c) * clip.jointCount; };
  for (uint32_t c = 0; c < frames; ++c) {
    if (c + 1 < frames || clip.cyclic) {
      appendFeature(f, pose(c), pose((c + 1) % frames), clip.rootSteps[c], dt);
    } else {
      // The last frame of a one-shot clip: the velocity it arrived with.
      Features back{clip.jointCount, {}, {}};
      appendFeature(back, pose(c - 1), pose(c), clip.rootSteps[c - 1], dt);
      for (uint32_t j = 0; j < clip.jointCount; ++j) {
        f.position.push_back(pose(c)[j].position);
        f.velocity.push_back(back.velocity[j]);
      }
    }
  }
  return f;
}

float distance(const Features& a, uint32_t i, const Features& b, uint32_t k, float velocityWeight) {
  double dp = 0.0, dv = 0.0;
  const glm::vec3 *pa = a.p(i), *pb = b.p(k), *va = a.v(i), *vb = b.v(k);
  for (uint32_t j = 0; j < a.joints; ++j) {
    const glm::vec3 d = pa[j] - pb[j], e = va[j] - vb[j];
    dp += double(glm::dot(d, d));
    dv += double(glm::dot(e, e));
  }
  return float(std::sqrt(dp / a.joints) + velocityWeight * std::sqrt(dv / a.joints));
}

void checkJoinable(const PrimaryGraph& graph, const ClipPoses& clip) {
  validatePrimaryGraph(graph);
  if (clip.jointCount != graph.jointCount || clip.parents != graph.parents)
    fail("clip ", clip.name, " (", clip.jointCount,
         " joints) does not share the primary graph's skeleton topology (", graph.jointCount,
         " joints): it cannot join the graph");
  const uint32_t frames = clip.frameCount();
  if (frames < 2 || clip.poses.size() != size_t(frames) * clip.jointCount)
    fail("clip ", clip.name, ": ", clip.poses.size(),
         " pose joints is not a whole number of frames (at least 2)");
  if (clip.rootSteps.size() != (clip.cyclic ? frames : frames - 1))
    fail("clip ", clip.name, ": ", clip.rootSteps.size(), " root steps for ", frames, " frames");
}

void addEdge(PrimaryGraph& graph, uint32_t from, uint32_t to, glm::vec3 step, uint32_t& counter) {
  std::vector<uint32_t>& next = graph.successors[from];
  if (std::find(next.begin(), next.end(), to) != next.end()) return;
  next.push_back(to);
  graph.rootStep[from].push_back(step);
  ++counter;
}

}  // namespace

float transitionDistance(const PrimaryGraph& graph, uint32_t node, const ClipPoses& clip,
                         uint32_t frame, const TransitionOptions& options) {
  checkJoinable(graph, clip);
  Features a{graph.jointCount, {}, {}};
  const uint32_t next = naturalSuccessor(graph, node);
  appendFeature(a, graph.pose(node), graph.pose(next),
                graph.rootStep[node][edgeIndex(graph, node, next)], graph.frameTime);
  return distance(a, 0, clipFeatures(clip, graph.frameTime), frame, options.velocityWeight);
}

TransitionReport addClipWithTransitions(PrimaryGraph& graph, const ClipPoses& clip,
                                        const TransitionOptions& options) {
  checkJoinable(graph, clip);
  if (!(options.threshold > 0.0f) || options.velocityWeight < 0.0f || options.maxPerFrame == 0)
    fail(
        "transition options: threshold must be > 0, velocity weight ≥ 0 and at least one "
        "transition per frame");
  const uint32_t nodes = uint32_t(graph.nodes.size()), frames = clip.frameCount();
  const Features a = graphFeatures(graph);
  const Features b = clipFeatures(clip, graph.frameTime);
  std::vector<float> d(size_t(nodes) * frames);
  TransitionReport report;
  report.bestDistance = INFINITY;
  for (uint32_t n = 0; n < nodes; ++n)
    for (uint32_t c = 0; c < frames; ++c) {
      d[size_t(n) * frames + c] = distance(a, n, b, c, options.velocityWeight);
      report.bestDistance = std::min(report.bestDistance, d[size_t(n) * frames + c]);
    }
  // Neighbours along the graph: a node's natural successor and the nodes it is natural after.
  std::vector<std::vector<uint32_t>> graphNeighbours(nodes);
  for (uint32_t n = 0; n < nodes; ++n) {
    const uint32_t next = naturalSuccessor(graph, n);
    graphNeighbours[n].push_back(next);
    graphNeighbours[next].push_back(n);
  }
  auto at = [&](uint32_t n, uint32_t c) { return d[size_t(n) * frames + c]; };
  auto isLocalMinimum = [&](uint32_t n, uint32_t c) {
    const float v = at(n, c);
    if (c > 0 && at(n, c - 1) < v) return false;
    if (c + 1 < frames && at(n, c + 1) < v) return false;
    if (clip.cyclic && frames > 2 &&
        (at(n, (c + 1) % frames) < v || at(n, (c + frames - 1) % frames) < v))
      return false;
    for (uint32_t m : graphNeighbours[n])
      if (at(m, c) < v) return false;
    return true;
  };

  uint32_t clipIndex = 0;
  for (const PrimaryNode& n : graph.nodes) clipIndex = std::max(clipIndex, n.clip + 1);
  report.clip = clipIndex;
  report.firstNode = nodes;
  for (uint32_t c = 0; c < frames; ++c) {
    graph.nodes.push_back({clipIndex, 0u, c});
    graph.poses.insert(graph.poses.end(), clip.poses.begin() + ptrdiff_t(c) * clip.jointCount,
                       clip.poses.begin() + ptrdiff_t(c + 1) * clip.jointCount);
    graph.successors.push_back({});
    graph.rootStep.push_back({});
    if (c + 1 < frames || clip.cyclic) {
      graph.successors.back().push_back(nodes + (c + 1) % frames);
      graph.rootStep.back().push_back(clip.rootSteps[c]);
    }
  }

  std::vector<std::pair<float, uint32_t>> candidates;
  for (uint32_t c = 0; c < frames; ++c) {
    candidates.clear();
    for (uint32_t n = 0; n < nodes; ++n)
      if (at(n, c) < options.threshold && isLocalMinimum(n, c)) candidates.push_back({at(n, c), n});
    std::sort(candidates.begin(), candidates.end());
    if (candidates.size() > options.maxPerFrame) candidates.resize(options.maxPerFrame);
    const bool hasNext = c + 1 < frames || clip.cyclic;
    for (const auto& [dist, n] : candidates) {
      // n looks like c: from n the character may go on as the clip does after c …
      if (hasNext) addEdge(graph, n, nodes + (c + 1) % frames, clip.rootSteps[c], report.intoClip);
      // … and from c it may go on as the graph does after n.
      const std::vector<uint32_t> next = graph.successors[n];
      const std::vector<glm::vec3> steps = graph.rootStep[n];
      for (size_t k = 0; k < next.size(); ++k)
        if (next[k] < nodes) addEdge(graph, nodes + c, next[k], steps[k], report.outOfClip);
    }
  }
  return report;
}

}  // namespace throng::secondary
