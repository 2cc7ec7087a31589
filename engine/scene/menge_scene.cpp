#include "scene/menge_scene.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "anim/speed_buckets.h"
#include "core/error.h"
#include "core/rng.h"
#include "crowd/nav_mesh.h"
#include "crowd/path_vectors.h"

namespace throng::scene {

namespace {

constexpr float kMinReach = 0.5f;  // metres

std::string where(const std::filesystem::path& file, int line) {
  return concat(file.string(), ":", line);
}

float distributionValue(const menge::Distribution& d) {
  switch (d.kind) {
    case menge::Distribution::Kind::Constant:
      return d.value;
    case menge::Distribution::Kind::Uniform:
      return 0.5f * (d.min + d.max);
    case menge::Distribution::Kind::Normal:
      return d.mean;
  }
  return d.value;
}

// Walls: explicit obstacle polygons and the nav meshes' obstacle edges.
crowd::Obstacles mengeWalls(const menge::MengeScenario& s) {
  crowd::Obstacles walls;
  for (const menge::ObstacleSet& set : s.scene.obstacleSets)
    for (const menge::Obstacle& o : set.obstacles)
      if (o.vertices.size() >= (o.closed ? 3u : 2u)) walls.addPolyline(o.vertices, o.closed);
  for (const menge::NavMesh& mesh : s.navMeshes)
    for (const menge::NavMesh::Obstacle& o : mesh.obstacles)
      walls.segments.push_back({mesh.vertices.at(o.v0), mesh.vertices.at(o.v1)});
  return walls;
}

struct GoalSetIndex {
  std::map<int, uint32_t> set;                // Menge goal set id → index
  std::vector<std::map<int, uint32_t>> goal;  // per set: goal id → index
};

GoalSetIndex mengeGoalSets(const menge::Behavior& b, crowd::GoalScene& scene) {
  GoalSetIndex index;
  for (const menge::GoalSet& set : b.goalSets) {
    index.set[set.id] = uint32_t(scene.goalSets.size());
    index.goal.emplace_back();
    crowd::GoalSet converted;
    for (const menge::Goal& g : set.goals) {
      index.goal.back()[g.id] = uint32_t(converted.goals.size());
      converted.goals.push_back(crowd::goalFromMenge(g));
    }
    scene.goalSets.push_back(std::move(converted));
  }
  return index;
}

crowd::GoalChoice mengeChoice(const menge::State& state, const GoalSetIndex& index,
                              const std::filesystem::path& file,
                              std::vector<std::string>& warnings) {
  using K = menge::GoalSelector::Kind;
  const menge::GoalSelector& g = state.goalSelector;
  crowd::GoalChoice choice;
  auto setOf = [&](int id) -> uint32_t {
    auto it = index.set.find(id);
    if (it == index.set.end())
      fail(where(file, g.line), ": goal selector of state '", state.name, "' names goal set ", id,
           ", which the behaviour does not define");
    return it->second;
  };
  if (state.velocity.kind == menge::VelocityComponent::Kind::Zero || g.kind == K::None ||
      g.kind == K::Identity) {
    choice.kind = crowd::GoalChoice::Kind::Identity;
    return choice;
  }
  if (g.kind == K::Mirror) {
    choice.kind = crowd::GoalChoice::Kind::Mirror;
    choice.mirrorX = g.mirrorX;
    choice.mirrorZ = g.mirrorY;  // Menge's y is Throng's z
    return choice;
  }
  choice.goalSet = setOf(g.goalSet);
  choice.sampleInside = true;
  switch (g.kind) {
    case K::Explicit: {
      choice.kind = crowd::GoalChoice::Kind::Explicit;
      const auto& goals = index.goal[choice.goalSet];
      auto it = goals.find(g.goal);
      if (it == goals.end())
        fail(where(file, g.line), ": goal ", g.goal, " is not in goal set ", g.goalSet);
      choice.goal = it->second;
      break;
    }
    case K::Random:
    case K::Weighted:
      choice.kind = crowd::GoalChoice::Kind::Random;
      break;
    case K::Nearest:
    case K::NearestNavMesh:
      choice.kind = crowd::GoalChoice::Kind::Nearest;
      break;
    default:
      warnings.push_back(concat(where(file, g.line), ": goal selector '", g.type,
                                "' has no equivalent: the nearest goal of the set is used"));
      choice.kind = crowd::GoalChoice::Kind::Nearest;
      break;
  }
  return choice;
}

// A transition's target state: the heaviest of a probabilistic target (warned).
uint32_t transitionTarget(const menge::Transition& t, const std::filesystem::path& file,
                          std::vector<std::string>& warnings) {
  if (t.targets.empty() || t.targets.front().stateIndex < 0) return crowd::kNoState;
  if (t.targets.size() > 1)
    warnings.push_back(concat(where(file, t.line),
                              ": a probabilistic target becomes its most "
                              "likely state"));
  const auto best =
      std::max_element(t.targets.begin(), t.targets.end(),
                       [](const menge::TransitionTarget& a, const menge::TransitionTarget& b) {
                         return a.weight < b.weight;
                       });
  return uint32_t(best->stateIndex);
}

void applyTransitions(const menge::Behavior& b, std::vector<crowd::GoalState>& states,
                      std::vector<std::string>& warnings) {
  using C = menge::Condition::Kind;
  for (const menge::Transition& t : b.transitions) {
    if (t.fromIndex < 0) continue;
    crowd::GoalState& s = states[size_t(t.fromIndex)];
    const uint32_t next = transitionTarget(t, b.source, warnings);
    if (s.next != crowd::kNoState && s.next != next)
      warnings.push_back(concat(where(b.source, t.line), ": a second transition from '", t.from,
                                "' to another state: the first one's target is kept"));
    if (s.next == crowd::kNoState) s.next = next;
    switch (t.condition.kind) {
      case C::GoalReached:
        s.onArrival = crowd::GoalState::Arrival::Wait;
        s.waitSeconds = 0.0f;
        if (t.condition.distance > 0.0f) s.reach = t.condition.distance;
        // Agents that avoid each other stop about a body width short of a point many share.
        if (s.reach < kMinReach) {
          warnings.push_back(concat(where(b.source, t.condition.line), ": goal_reached distance ",
                                    s.reach, " m is taken as ", kMinReach,
                                    " m (agents keep their radius from each other at goals)"));
          s.reach = kMinReach;
        }
        break;
      case C::Timer:
        s.leaveAfter = std::max(0.0f, distributionValue(t.condition.duration));
        break;
      case C::Auto:
        s.leaveAfter = 0.0f;
        break;
      default:
        warnings.push_back(concat(where(b.source, t.condition.line), ": condition '",
                                  t.condition.type,
                                  "' has no equivalent: the transition is dropped"));
        break;
    }
  }
}

crowd::GoalScene mengeGoals(const menge::MengeScenario& s, std::vector<std::string>& warnings) {
  crowd::GoalScene goals;
  const menge::Behavior& b = s.behavior;
  const GoalSetIndex index = mengeGoalSets(b, goals);
  std::vector<crowd::GoalState> states;
  std::map<std::string, uint32_t> stateIndex;
  for (const menge::State& state : b.states) {
    crowd::GoalState g;
    g.choice = mengeChoice(state, index, b.source, warnings);
    g.onArrival = crowd::GoalState::Arrival::Stop;  // until a goal_reached transition says more
    stateIndex[state.name] = uint32_t(states.size());
    states.push_back(g);
  }
  applyTransitions(b, states, warnings);
  // One machine per Menge agent group: the same states, its own initial state and speed.
  for (const menge::AgentGroup& group : s.scene.groups) {
    crowd::GoalBehavior behavior;
    behavior.states = states;
    auto it = stateIndex.find(group.state);
    if (it == stateIndex.end())
      fail(where(s.scene.source, group.line), ": initial state '", group.state,
           "' is not a state of the behaviour");
    behavior.initial = it->second;
    if (group.profileIndex >= 0)
      behavior.maxSpeed = s.scene.profiles[size_t(group.profileIndex)].maxSpeed;
    goals.groups.push_back(std::move(behavior));
  }
  for (const menge::AgentStart& a : s.scene.agents) goals.agentGroup.push_back(a.group);
  if (!s.navMeshes.empty()) goals.navMesh = crowd::navMeshFromMenge(s.navMeshes.front());
  if (!s.roadMaps.empty()) goals.roadMap = crowd::roadMapFromMenge(s.roadMaps.front());
  return goals;
}

void growBounds(MengeSceneResult& r, glm::vec2 p) {
  r.boundsMin = glm::min(r.boundsMin, p);
  r.boundsMax = glm::max(r.boundsMax, p);
}

}  // namespace

MengeSceneResult mengeScene(const menge::MengeScenario& s, const anim::ClipPair& clips,
                            uint64_t seed, float bucketWidth) {
  if (s.scene.agents.empty()) fail(s.project.string(), ": the scenario has no agent");
  MengeSceneResult r;
  r.warnings = s.warnings;
  anim::MotionPair pair = anim::makeMotionPair(clips.slow, clips.fast);
  const float slow = anim::clipRootSpeed(pair.slow), fast = anim::clipRootSpeed(pair.fast);
  const size_t n = s.scene.agents.size();
  SceneSetup& setup = r.setup;
  setup.crowd.resize(n);
  Rng rng(seed);
  r.boundsMin = r.boundsMax = s.scene.agents.front().position;
  float radius = 0.0f;
  for (size_t i = 0; i < n; ++i) {
    const menge::AgentStart& a = s.scene.agents[i];
    const menge::AgentGroup& g = s.scene.groups.at(a.group);
    const menge::AgentProfile* profile =
        g.profileIndex >= 0 ? &s.scene.profiles[size_t(g.profileIndex)] : nullptr;
    const float speed = profile ? profile->prefSpeed : 1.34f;
    radius = std::max(radius, profile ? profile->radius : 0.19f);
    float w = crowd::speedWeight(speed, slow, fast);
    if (bucketWidth > 0.0f) w = anim::quantizeSpeed(w, bucketWidth);
    setup.crowd.placement[i] = glm::vec4(a.position.x, 0.0f, a.position.y, 0.0f);
    setup.crowd.motion[i] = gpu_types::makeMotion(rng.uniform(0.0f, 1.0f), w, w, 1.0f);
    growBounds(r, a.position);
  }
  setup.pairs.push_back(std::move(pair));
  setup.groupFirst = {0, uint32_t(n)};
  setup.walls = mengeWalls(s);
  for (const crowd::Segment& seg : setup.walls.segments) {
    growBounds(r, seg.a);
    growBounds(r, seg.b);
  }
  setup.steering.emplace();
  setup.steering->avoidance.radius = std::max(radius, 0.1f);
  setup.steering->avoidance.seed = uint32_t(seed);
  setup.steering->goals = mengeGoals(s, r.warnings);
  setup.steering->goals->seed = uint32_t(seed);
  // Road maps route around the walls by visibility, as Menge's do.
  setup.steering->goals->roadMap.walls = setup.walls.segments;
  for (const crowd::GoalSet& set : setup.steering->goals->goalSets)
    for (const crowd::Goal& goal : set.goals) growBounds(r, goal.center);
  return r;
}

}  // namespace throng::scene
