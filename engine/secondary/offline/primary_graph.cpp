#include "secondary/offline/primary_graph.h"

#include <algorithm>
#include <cmath>

#include "anim/reference_synth.h"
#include "core/error.h"
#include "core/math.h"
#include "synth/motion_cache.h"

namespace throng::secondary {

float runCycleDuration(const anim::MotionPair& pair, float w) {
  return pair.slow.duration() * (1.0f - w) + pair.fast.duration() * w;
}

uint32_t runCycleFrames(const anim::MotionPair& pair, float w, float frameTime) {
  THRONG_CHECK(frameTime > 0.0f, "frame time must be positive");
  long frames = std::lround(runCycleDuration(pair, w) / frameTime);
  return uint32_t(std::max(2l, frames));
}

PrimaryGraph buildRunGraph(const anim::MotionPair& pair, const anim::Skeleton& skeleton,
                           float bucketWidth) {
  synth::validateCacheOptions(
      synth::MotionCacheOptions{.enabled = true, .bucketWidth = bucketWidth});
  if (skeleton.jointCount() != pair.jointCount())
    fail("buildRunGraph: skeleton has ", skeleton.jointCount(), " joints, the motion pair ",
         pair.jointCount());
  PrimaryGraph graph;
  graph.frameTime = pair.slow.frameTime;
  graph.jointCount = uint32_t(pair.jointCount());
  graph.parents = pair.parents;
  for (const anim::Joint& joint : skeleton.joints) graph.jointNames.push_back(joint.name);

  const uint32_t buckets = synth::speedBucketCount(bucketWidth);
  std::vector<uint32_t> firstNode(buckets), frames(buckets);
  std::vector<anim::PoseJoint> pose(graph.jointCount);
  for (uint32_t b = 0; b < buckets; ++b) {
    const float w = synth::bucketSpeed(b, bucketWidth);
    frames[b] = runCycleFrames(pair, w, graph.frameTime);
    firstNode[b] = uint32_t(graph.nodes.size());
    // The crowd's mean travel per frame at this speed; its sum over a cycle is exactly the
    // cycle travel the synthesizer moves a character by, without the frame-grid jitter.
    const glm::vec3 travel = pair.slow.cycleTravel * (1.0f - w) + pair.fast.cycleTravel * w;
    const glm::vec3 step = glm::vec3(travel.x, 0.0f, travel.z) / float(frames[b]);
    for (uint32_t f = 0; f < frames[b]; ++f) {
      // A hair past f / F so a phase that lands on a texture frame boundary is not rounded
      // down to the previous frame by float division.
      const float phase = float(f) / float(frames[b]) + 1e-6f;
      anim::poseCharacterSpace(pair, phase, w, pose);
      for (const anim::PoseJoint& joint : pose)
        graph.poses.push_back({joint.position, joint.rotation});
      graph.nodes.push_back({0u, b, f});
      graph.rootStep.push_back({});
      graph.successors.push_back({});
      if (f + 1 < frames[b]) {
        graph.successors.back().push_back(firstNode[b] + f + 1);
        graph.rootStep.back().push_back(step);
      }
    }
  }
  // Cycle ends: the synthesizer switches w only when the phase wraps.
  for (uint32_t b = 0; b < buckets; ++b) {
    const uint32_t last = firstNode[b] + frames[b] - 1;
    const glm::vec3 step = graph.rootStep[firstNode[b]].front();
    for (uint32_t to = 0; to < buckets; ++to) {
      graph.successors[last].push_back(firstNode[to]);
      graph.rootStep[last].push_back(step);
    }
  }
  return graph;
}

PrimaryGraph buildRunGraph(const anim::ClipPair& clips, float bucketWidth) {
  return buildRunGraph(anim::makeMotionPair(clips.slow, clips.fast), clips.slow.skeleton,
                       bucketWidth);
}

uint32_t naturalSuccessor(const PrimaryGraph& graph, uint32_t node) {
  const std::vector<uint32_t>& next = graph.successors.at(node);
  THRONG_CHECK(!next.empty(), "node ", node, " has no successor");
  const PrimaryNode& from = graph.nodes[node];
  for (uint32_t to : next) {
    const PrimaryNode& n = graph.nodes[to];
    if (n.clip == from.clip && n.bucket == from.bucket && n.frame == from.frame + 1) return to;
  }
  for (uint32_t to : next) {
    const PrimaryNode& n = graph.nodes[to];
    if (n.clip == from.clip && n.bucket == from.bucket && n.frame == 0) return to;
  }
  return next.front();
}

uint32_t edgeIndex(const PrimaryGraph& graph, uint32_t from, uint32_t to) {
  const std::vector<uint32_t>& next = graph.successors.at(from);
  auto it = std::find(next.begin(), next.end(), to);
  if (it == next.end()) fail("primary graph: no edge from node ", from, " to node ", to);
  return uint32_t(it - next.begin());
}

ClipPoses clipPoses(const anim::Clip& clip, bool cyclic) {
  if (clip.frameCount < 2)
    fail(clip.name, ": a clip joining the primary graph needs at least 2 frames");
  ClipPoses out;
  out.name = clip.name;
  out.jointCount = uint32_t(clip.jointCount());
  out.cyclic = cyclic;
  out.parents = clip.skeleton.parents();
  const std::vector<int32_t>& parents = out.parents;
  for (int f = 0; f < clip.frameCount; ++f) {
    const size_t base = out.poses.size();
    for (int j = 0; j < clip.jointCount(); ++j) {
      const glm::vec4 q = clip.rotation(f, j);
      const glm::vec3 o = clip.offset(f, j);
      const int p = parents[size_t(j)];
      if (p < 0) {
        out.poses.push_back({glm::vec3(0.0f, o.y, 0.0f), q});
      } else {
        const NodeJoint& parent = out.poses[base + size_t(p)];
        out.poses.push_back(
            {parent.position + quatRotate(parent.rotation, o), quatMul(parent.rotation, q)});
      }
    }
  }
  auto horizontal = [](glm::vec3 d) { return glm::vec3(d.x, 0.0f, d.z); };
  for (int f = 0; f + 1 < clip.frameCount; ++f)
    out.rootSteps.push_back(
        horizontal(clip.rootPositions[size_t(f + 1)] - clip.rootPositions[size_t(f)]));
  if (cyclic)
    out.rootSteps.push_back(
        horizontal(clip.rootPositions.front() + clip.cycleTravel - clip.rootPositions.back()));
  return out;
}

namespace {

// Iterative Tarjan (explicit stack: graphs of many thousand nodes would overflow recursion).
std::vector<int32_t> componentOf(const PrimaryGraph& graph, uint32_t& componentCount) {
  const uint32_t n = uint32_t(graph.nodes.size());
  std::vector<int32_t> index(n, -1), low(n, 0), component(n, -1);
  std::vector<uint8_t> onStack(n, 0);
  std::vector<uint32_t> stack;
  std::vector<std::pair<uint32_t, uint32_t>> work;  // (node, next successor to visit)
  int32_t counter = 0;
  componentCount = 0;
  for (uint32_t root = 0; root < n; ++root) {
    if (index[root] >= 0) continue;
    work.push_back({root, 0});
    while (!work.empty()) {
      auto& [v, next] = work.back();
      if (next == 0 && index[v] < 0) {
        index[v] = low[v] = counter++;
        stack.push_back(v);
        onStack[v] = 1;
      }
      const std::vector<uint32_t>& succ = graph.successors[v];
      if (next < succ.size()) {
        const uint32_t w = succ[next++];
        if (index[w] < 0) {
          work.push_back({w, 0});
        } else if (onStack[w]) {
          low[v] = std::min(low[v], index[w]);
        }
        continue;
      }
      if (low[v] == index[v]) {
        uint32_t w;
        do {
          w = stack.back();
          stack.pop_back();
          onStack[w] = 0;
          component[w] = int32_t(componentCount);
        } while (w != v);
        ++componentCount;
      }
      const uint32_t finished = v;
      work.pop_back();
      if (!work.empty()) low[work.back().first] = std::min(low[work.back().first], low[finished]);
    }
  }
  return component;
}

}  // namespace

std::vector<int32_t> pruneToStronglyConnected(PrimaryGraph& graph) {
  validatePrimaryGraph(graph);
  uint32_t count = 0;
  const std::vector<int32_t> component = componentOf(graph, count);
  const uint32_t n = uint32_t(graph.nodes.size());
  std::vector<uint32_t> size(count, 0), lowest(count, n), edges(count, 0);
  for (uint32_t v = 0; v < n; ++v) {
    const uint32_t c = uint32_t(component[v]);
    ++size[c];
    lowest[c] = std::min(lowest[c], v);
    for (uint32_t w : graph.successors[v]) edges[c] += component[w] == component[v] ? 1u : 0u;
  }
  int64_t best = -1;
  for (uint32_t c = 0; c < count; ++c) {
    if (edges[c] == 0) continue;  // a lone node without a self-loop is no cycle
    if (best < 0 || size[c] > size[size_t(best)] ||
        (size[c] == size[size_t(best)] && lowest[c] < lowest[size_t(best)]))
      best = c;
  }
  if (best < 0)
    fail("primary graph: no cycle at all (", n, " nodes), nothing to keep after pruning");

  std::vector<int32_t> remap(n, -1);
  uint32_t kept = 0;
  for (uint32_t v = 0; v < n; ++v)
    if (component[v] == best) remap[v] = int32_t(kept++);
  PrimaryGraph out;
  out.frameTime = graph.frameTime;
  out.jointCount = graph.jointCount;
  out.parents = graph.parents;
  out.jointNames = graph.jointNames;
  for (uint32_t v = 0; v < n; ++v) {
    if (remap[v] < 0) continue;
    out.nodes.push_back(graph.nodes[v]);
    const NodeJoint* pose = graph.pose(v);
    out.poses.insert(out.poses.end(), pose, pose + graph.jointCount);
    out.successors.push_back({});
    out.rootStep.push_back({});
    for (size_t k = 0; k < graph.successors[v].size(); ++k) {
      const int32_t to = remap[graph.successors[v][k]];
      if (to < 0) continue;
      out.successors.back().push_back(uint32_t(to));
      out.rootStep.back().push_back(graph.rootStep[v][k]);
    }
  }
  graph = std::move(out);
  return remap;
}

bool isStronglyConnected(const PrimaryGraph& graph) {
  if (graph.nodes.empty()) return false;
  for (const auto& next : graph.successors)
    if (next.empty()) return false;
  uint32_t count = 0;
  componentOf(graph, count);
  return count == 1;
}

void validatePrimaryGraph(const PrimaryGraph& graph) {
  const size_t n = graph.nodes.size();
  auto bad = [](const auto&... what) { fail("primary graph: ", what...); };
  if (graph.frameTime <= 0.0f) bad("frame time ", graph.frameTime, " must be positive");
  if (graph.parents.size() != graph.jointCount)
    bad(graph.parents.size(), " parents for ", graph.jointCount, " joints");
  if (graph.jointNames.size() != graph.jointCount)
    bad(graph.jointNames.size(), " joint names for ", graph.jointCount, " joints");
  for (uint32_t j = 0; j < graph.jointCount; ++j)
    if (graph.parents[j] >= int32_t(j) || graph.parents[j] < -1)
      bad("joint ", j, " has parent ", graph.parents[j]);
  if (graph.poses.size() != n * graph.jointCount)
    bad(graph.poses.size(), " pose joints for ", n, " nodes");
  if (graph.successors.size() != n || graph.rootStep.size() != n)
    bad(graph.successors.size(), " successor lists and ", graph.rootStep.size(), " step lists for ",
        n, " nodes");
  for (size_t v = 0; v < n; ++v) {
    if (graph.rootStep[v].size() != graph.successors[v].size())
      bad("node ", v, " has ", graph.successors[v].size(), " successors but ",
          graph.rootStep[v].size(), " steps");
    for (uint32_t w : graph.successors[v])
      if (w >= n) bad("node ", v, " has successor ", w, " of ", n, " nodes");
  }
}

}  // namespace throng::secondary
