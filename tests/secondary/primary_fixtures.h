#pragma once
// Shared by the graph and cloth suites: the crowd's run graph on the built-in gait, a third
// gait (a jog) that shares its skeleton, and a one-joint graph for cloth on its own.
#include <memory>

#include "anim/default_clips.h"
#include "anim/gait.h"
#include "secondary/offline/primary_graph.h"

namespace throng::test {

inline constexpr float kTestBucketWidth = 0.05f;

inline const anim::ClipPair& defaultClips() {
  static const anim::ClipPair clips = anim::defaultRunPair();
  return clips;
}

inline std::shared_ptr<const secondary::PrimaryGraph> defaultRunGraph() {
  static const auto graph = std::make_shared<const secondary::PrimaryGraph>(
      secondary::buildRunGraph(defaultClips(), kTestBucketWidth));
  return graph;
}

// A slower run cycle from the project's own gait generator: the "other clip" of the tests.
inline anim::Clip jogClip() {
  anim::GaitParams jog = anim::slowRunGait();
  jog.name = "jog";
  jog.speed = 1.9;
  jog.cycleFrames = 26;
  anim::Clip clip = anim::toClip(anim::generateGait(jog));
  clip.name = jog.name;
  clip.cycleTravel = glm::vec3(0.0f, 0.0f, float(anim::gaitCycleTravel(jog)));
  return clip;
}

// The first node of bucket b's cycle.
inline uint32_t cycleStart(const secondary::PrimaryGraph& graph, uint32_t bucket) {
  for (uint32_t n = 0; n < graph.nodes.size(); ++n)
    if (graph.nodes[n].clip == 0 && graph.nodes[n].bucket == bucket && graph.nodes[n].frame == 0)
      return n;
  return UINT32_MAX;
}

// One joint at the origin, one node looping onto itself, no travel.
inline std::shared_ptr<const secondary::PrimaryGraph> standingGraph() {
  auto graph = std::make_shared<secondary::PrimaryGraph>();
  graph->jointCount = 1;
  graph->parents = {-1};
  graph->jointNames = {"Anchor"};
  graph->nodes = {{0, 0, 0}};
  graph->poses = {{glm::vec3(0.0f), glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)}};
  graph->successors = {{0}};
  graph->rootStep = {{glm::vec3(0.0f)}};
  return graph;
}

}  // namespace throng::test
