#include "crowd/goals.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "crowd/avoidance.h"
#include "menge/menge.h"

namespace throng::crowd {
namespace {

constexpr float kPi = 3.14159265358979f;

// A number in [0, 1) from (a, b, c, seed): the hash chain of the steering pass's draws.
float unitRandom(uint32_t a, uint32_t b, uint32_t c, uint32_t seed) {
  const uint32_t h = pcgHash(a ^ pcgHash(b ^ pcgHash(c ^ pcgHash(seed))));
  return float(h >> 8) * (1.0f / 16777216.0f);
}

glm::vec2 axisX(const Goal& goal) {
  return goal.shape == Goal::Shape::OrientedBox
             ? glm::vec2(std::cos(goal.angle), std::sin(goal.angle))
             : glm::vec2(1.0f, 0.0f);
}
glm::vec2 toLocal(const Goal& goal, glm::vec2 p) {
  const glm::vec2 ax = axisX(goal), d = p - goal.center;
  return {glm::dot(d, ax), glm::dot(d, glm::vec2(-ax.y, ax.x))};
}
glm::vec2 fromLocal(const Goal& goal, glm::vec2 q) {
  const glm::vec2 ax = axisX(goal);
  return goal.center + q.x * ax + q.y * glm::vec2(-ax.y, ax.x);
}

uint32_t weightedDraw(const GoalSet& set, float u) {
  float total = 0.0f;
  for (const Goal& g : set.goals) total += g.weight;
  float x = u * total;
  for (uint32_t k = 0; k < set.goals.size(); ++k) {
    if (x < set.goals[k].weight) return k;
    x -= set.goals[k].weight;
  }
  return uint32_t(set.goals.size() - 1);
}

void validateState(const GoalScene& scene, const GoalBehavior& group, size_t g, size_t s,
                   std::vector<std::string>& problems) {
  const GoalState& st = group.states[s];
  const std::string where = concat("group ", g, " state ", s, ": ");
  if (st.next != kNoState && st.next >= group.states.size())
    problems.push_back(concat(where, "next state ", st.next, " of ", group.states.size()));
  if (!(st.reach >= 0.0f) || !(st.waitSeconds >= 0.0f) || !std::isfinite(st.waitSeconds) ||
      !(st.leaveAfter >= 0.0f))
    problems.push_back(where + "reach, wait and leave-after times must be 0 or more");
  if (st.choice.ownPoint()) return;
  if (st.choice.goalSet >= scene.goalSets.size()) {
    problems.push_back(
        concat(where, "goal set ", st.choice.goalSet, " of ", scene.goalSets.size()));
    return;
  }
  const GoalSet& set = scene.goalSets[st.choice.goalSet];
  if (set.goals.empty())
    problems.push_back(concat(where, "goal set ", st.choice.goalSet, " is empty"));
  if (st.choice.kind == GoalChoice::Kind::Explicit && st.choice.goal >= set.goals.size())
    problems.push_back(concat(where, "goal ", st.choice.goal, " of ", set.goals.size()));
}

}  // namespace

Goal pointGoal(glm::vec2 p) {
  Goal g;
  g.center = p;
  return g;
}
Goal circleGoal(glm::vec2 center, float radius) {
  Goal g;
  g.shape = Goal::Shape::Circle;
  g.center = center;
  g.radius = radius;
  return g;
}
Goal boxGoal(glm::vec2 min, glm::vec2 max) {
  Goal g;
  g.shape = Goal::Shape::Box;
  g.center = 0.5f * (min + max);
  g.halfSize = 0.5f * (max - min);
  return g;
}
Goal orientedBoxGoal(glm::vec2 center, glm::vec2 halfSize, float angle) {
  Goal g;
  g.shape = Goal::Shape::OrientedBox;
  g.center = center;
  g.halfSize = halfSize;
  g.angle = angle;
  return g;
}

float goalDistance(const Goal& goal, glm::vec2 p) {
  switch (goal.shape) {
    case Goal::Shape::Point:
      return glm::distance(p, goal.center);
    case Goal::Shape::Circle:
      return std::max(0.0f, glm::distance(p, goal.center) - goal.radius);
    default:
      return glm::length(glm::max(glm::abs(toLocal(goal, p)) - goal.halfSize, glm::vec2(0.0f)));
  }
}

glm::vec2 closestGoalPoint(const Goal& goal, glm::vec2 p) {
  switch (goal.shape) {
    case Goal::Shape::Point:
      return goal.center;
    case Goal::Shape::Circle: {
      const glm::vec2 d = p - goal.center;
      const float len = glm::length(d);
      return len <= goal.radius ? p : goal.center + d * (goal.radius / len);
    }
    default:
      return fromLocal(goal, glm::clamp(toLocal(goal, p), -goal.halfSize, goal.halfSize));
  }
}

glm::vec2 sampleGoalPoint(const Goal& goal, uint32_t agent, uint32_t draw, uint32_t seed) {
  const float u = unitRandom(agent, draw, 0u, seed), v = unitRandom(agent, draw, 1u, seed);
  switch (goal.shape) {
    case Goal::Shape::Point:
      return goal.center;
    case Goal::Shape::Circle: {
      const float r = goal.radius * std::sqrt(u), a = 2.0f * kPi * v;
      return goal.center + r * glm::vec2(std::cos(a), std::sin(a));
    }
    default:
      return fromLocal(goal, (2.0f * glm::vec2(u, v) - 1.0f) * goal.halfSize);
  }
}

std::vector<std::string> validateGoal(const Goal& goal) {
  std::vector<std::string> problems;
  const bool finite = std::isfinite(goal.center.x) && std::isfinite(goal.center.y) &&
                      std::isfinite(goal.radius) && std::isfinite(goal.halfSize.x) &&
                      std::isfinite(goal.halfSize.y) && std::isfinite(goal.angle);
  if (!finite) problems.push_back("a goal has a value that is not finite");
  if (goal.radius < 0.0f || goal.halfSize.x < 0.0f || goal.halfSize.y < 0.0f)
    problems.push_back("a goal has a negative size");
  if (!(goal.weight >= 0.0f)) problems.push_back("a goal has a negative weight");
  return problems;
}

std::vector<std::string> validateGoalScene(const GoalScene& scene, size_t agents) {
  std::vector<std::string> problems;
  if (scene.agentGroup.size() != agents)
    problems.push_back(
        concat(scene.agentGroup.size(), " agent groups given for ", agents, " agents"));
  for (size_t i = 0; i < scene.agentGroup.size(); ++i)
    if (scene.agentGroup[i] != kNoState && scene.agentGroup[i] >= scene.groups.size()) {
      problems.push_back(
          concat("agent ", i, " is in group ", scene.agentGroup[i], " of ", scene.groups.size()));
      break;
    }
  for (const GoalSet& set : scene.goalSets)
    for (const Goal& goal : set.goals)
      for (std::string& p : validateGoal(goal)) problems.push_back(std::move(p));
  for (size_t g = 0; g < scene.groups.size(); ++g) {
    const GoalBehavior& group = scene.groups[g];
    if (group.initial >= group.states.size())
      problems.push_back(
          concat("group ", g, " starts in state ", group.initial, " of ", group.states.size()));
    if (!(group.maxSpeed > 0.0f))
      problems.push_back(concat("group ", g, ": max speed must be > 0"));
    for (size_t s = 0; s < group.states.size(); ++s) validateState(scene, group, g, s, problems);
  }
  if (!(scene.waypointReach > 0.0f)) problems.push_back("the waypoint reach must be > 0");
  if (!(scene.cornerClearance >= 0.0f)) problems.push_back("the corner clearance must be >= 0");
  return problems;
}

Goal goalFromMenge(const menge::Goal& goal) {
  Goal g;
  switch (goal.kind) {
    case menge::Goal::Kind::Point:
      g = pointGoal(goal.position);
      break;
    case menge::Goal::Kind::Circle:
      g = circleGoal(goal.position, goal.radius);
      break;
    case menge::Goal::Kind::AABB:
      g = boxGoal(goal.min, goal.max);
      break;
    case menge::Goal::Kind::OBB: {
      // Menge's pivot is a corner; the box extends along its rotated axes from it.
      const float a = goal.angle * kPi / 180.0f;
      const glm::vec2 half(0.5f * goal.width, 0.5f * goal.height);
      const glm::vec2 ax(std::cos(a), std::sin(a)), az(-ax.y, ax.x);
      g = orientedBoxGoal(goal.position + half.x * ax + half.y * az, half, a);
      break;
    }
  }
  g.weight = goal.weight;
  return g;
}

GoalMachine::GoalMachine(GoalScene scene, size_t agents) : scene_(std::move(scene)) {
  const std::vector<std::string> problems = validateGoalScene(scene_, agents);
  if (!problems.empty()) fail("goals: ", problems.front());
  agents_.resize(agents);
  paths_.resize(agents);
  shared_.resize(scene_.groups.size());
  for (size_t g = 0; g < scene_.groups.size(); ++g)
    shared_[g].assign(scene_.groups[g].states.size(), kNoState);
}

std::vector<uint32_t> GoalMachine::evaluate(std::span<const glm::vec2> positions, double seconds,
                                            std::span<const uint32_t> waypoints) {
  if (positions.size() != agents_.size())
    fail("goals: ", positions.size(), " positions for ", agents_.size(), " agents");
  if (!waypoints.empty() && waypoints.size() != agents_.size())
    fail("goals: ", waypoints.size(), " waypoint indices for ", agents_.size(), " agents");
  std::vector<uint32_t> changed;
  for (uint32_t i = 0; i < agents_.size(); ++i) {
    const uint32_t group = scene_.agentGroup[i];
    if (group == kNoState) continue;
    if (!started_) {
      enter(i, scene_.groups[group].initial, positions[i], seconds);
      changed.push_back(i);
      continue;
    }
    const uint32_t* waypoint = waypoints.empty() ? nullptr : &waypoints[i];
    const bool joined = joinsCrowdAtGoal(i, positions, seconds, waypoint);
    crowdArrivals_ += joined ? 1 : 0;
    if (step(i, positions[i], seconds, joined) || replanIfStuck(i, positions[i], seconds, waypoint))
      changed.push_back(i);
  }
  started_ = true;
  return changed;
}

void GoalMachine::enter(uint32_t agent, uint32_t state, glm::vec2 p, double seconds) {
  AgentGoal& a = agents_[agent];
  a.state = state;
  a.enteredAt = seconds;
  a.reachedAt = -1.0;
  a.done = false;
  choose(agent, p, false);
  plan(agent, p, seconds);
  // Staying where it stands, the agent is there on entry: it arrives now, not at the next
  // evaluation, by when the crowd may have pushed it off the spot.
  const GoalState& st = scene_.groups[scene_.agentGroup[agent]].states[state];
  if (st.choice.kind == GoalChoice::Kind::Identity &&
      st.onArrival != GoalState::Arrival::NextGoal) {
    a.reachedAt = seconds;
    a.done = st.onArrival == GoalState::Arrival::Stop;
  }
}

void GoalMachine::choose(uint32_t agent, glm::vec2 p, bool another) {
  AgentGoal& a = agents_[agent];
  const uint32_t group = scene_.agentGroup[agent];
  const GoalChoice& c = scene_.groups[group].states[a.state].choice;
  ++a.visits;
  if (c.ownPoint()) {
    a.goal = 0;
    a.target = p;
    if (c.kind == GoalChoice::Kind::Mirror)
      a.target = glm::vec2(c.mirrorX ? -p.x : p.x, c.mirrorZ ? -p.y : p.y);
    return;
  }
  a.arrivedSet = kNoState;  // off to another goal: no longer in the crowd at the last one
  const GoalSet& set = scene_.goalSets[c.goalSet];
  const uint32_t n = uint32_t(set.goals.size());
  uint32_t g = 0;
  switch (c.kind) {
    case GoalChoice::Kind::Explicit:
      g = another ? (a.goal + 1) % n : c.goal;
      break;
    case GoalChoice::Kind::Shared: {
      uint32_t& shared = shared_[group][a.state];
      if (shared == kNoState)
        shared = weightedDraw(set, unitRandom(group, a.state, 2u, scene_.seed));
      g = another ? (a.goal + 1) % n : shared;
      break;
    }
    case GoalChoice::Kind::Random:
      g = weightedDraw(set, unitRandom(agent, a.visits, 3u, scene_.seed));
      if (another && g == a.goal) g = (g + 1) % n;
      break;
    default: {  // Nearest
      float best = std::numeric_limits<float>::infinity();
      for (uint32_t k = 0; k < n; ++k) {
        const float d = goalDistance(set.goals[k], p);
        if ((!another || k != a.goal || n == 1) && d < best) {
          best = d;
          g = k;
        }
      }
    }
  }
  a.goal = g;
  const Goal& goal = set.goals[g];
  a.target = c.sampleInside ? sampleGoalPoint(goal, agent, a.visits, scene_.seed)
                            : closestGoalPoint(goal, p);
}

bool GoalMachine::step(uint32_t agent, glm::vec2 p, double seconds, bool joinedCrowd) {
  AgentGoal& a = agents_[agent];
  if (a.done) return false;
  const GoalState& st = scene_.groups[scene_.agentGroup[agent]].states[a.state];
  const bool identity = st.choice.ownPoint();
  const Goal goal =
      identity ? pointGoal(a.target) : scene_.goalSets[st.choice.goalSet].goals[a.goal];
  if (a.reachedAt < 0.0 && (goalDistance(goal, p) <= st.reach || joinedCrowd)) {
    a.reachedAt = seconds;
    if (!identity) {
      a.arrivedSet = st.choice.goalSet;
      a.arrivedGoal = a.goal;
    }
    if (st.onArrival == GoalState::Arrival::Stop) {
      a.done = true;
      return false;
    }
    if (st.onArrival == GoalState::Arrival::NextGoal) {
      a.reachedAt = -1.0;
      choose(agent, p, true);
      plan(agent, p, seconds);
      return true;
    }
  }
  if (a.reachedAt >= 0.0 && seconds - a.reachedAt >= st.waitSeconds) {
    if (st.next == kNoState) {
      a.done = true;
      return false;
    }
    enter(agent, st.next, p, seconds);
    return true;
  }
  if (st.next != kNoState && seconds - a.enteredAt >= double(st.leaveAfter)) {
    enter(agent, st.next, p, seconds);
    return true;
  }
  return false;
}

bool GoalMachine::joinsCrowdAtGoal(uint32_t agent, std::span<const glm::vec2> positions,
                                   double seconds, const uint32_t* waypoint) const {
  const AgentGoal& a = agents_[agent];
  if (a.done || a.reachedAt >= 0.0 || !(scene_.crowdReach > 0.0f) ||
      !(scene_.stuckSeconds > 0.0f) || seconds - a.progressAt < double(scene_.stuckSeconds))
    return false;
  const GoalState& st = scene_.groups[scene_.agentGroup[agent]].states[a.state];
  if (st.choice.ownPoint()) return false;
  const glm::vec2 p = positions[agent];
  if (waypoint && (*waypoint + 1 < paths_[agent].size() || !seesWaypoint(agent, p, *waypoint)))
    return false;  // not yet heading straight for its goal, or lost (planned again instead)
  for (uint32_t j = 0; j < agents_.size(); ++j)
    if (j != agent && agents_[j].arrivedSet == st.choice.goalSet &&
        agents_[j].arrivedGoal == a.goal && glm::distance(positions[j], p) <= scene_.crowdReach)
      return true;
  return false;
}

bool GoalMachine::seesWaypoint(uint32_t agent, glm::vec2 p, uint32_t waypoint) const {
  const std::vector<glm::vec2>& path = paths_[agent];
  const glm::vec2 w = path[std::clamp<size_t>(waypoint, 1, path.size() - 1)];
  // Off the mesh (a crowd pushes agents a little over its edges), seen from the nearest point on
  // it: the mesh does not say what lies beyond its edges.
  if (!scene_.navMesh.empty())
    return visibleOnMesh(scene_.navMesh, closestMeshPoint(scene_.navMesh, p), w);
  return visible(scene_.roadMap.walls, p, w);
}

bool GoalMachine::replanIfStuck(uint32_t agent, glm::vec2 p, double seconds,
                                const uint32_t* waypoint) {
  AgentGoal& a = agents_[agent];
  if (a.done || a.reachedAt >= 0.0 || !(scene_.stuckSeconds > 0.0f)) return false;
  const float remaining = remainingPathLength(paths_[agent], p);
  if (remaining <= a.bestRemaining - scene_.stuckDistance) {
    a.bestRemaining = remaining;
    a.progressAt = seconds;
    return false;
  }
  if (seconds - a.progressAt < double(scene_.stuckSeconds)) return false;
  if (scene_.navMesh.empty() && scene_.roadMap.empty()) return false;  // the same line again
  if (waypoint && seesWaypoint(agent, p, *waypoint)) return false;     // held back in a queue
  plan(agent, p, seconds);
  ++stuckPlans_;
  return true;
}

void GoalMachine::plan(uint32_t agent, glm::vec2 p, double seconds) {
  AgentGoal& a = agents_[agent];
  PlannedPath path = planPath(scene_.navMesh, scene_.roadMap, p, a.target, scene_.cornerClearance);
  paths_[agent] = std::move(path.points);
  if (paths_[agent].size() < 2) paths_[agent].push_back(a.target);
  a.bestRemaining = remainingPathLength(paths_[agent], p);
  a.progressAt = seconds;
  ++plans_;
  if (path.partial) ++partialPlans_;
}

uint32_t GoalMachine::agentsAtGoal() const {
  return uint32_t(
      std::count_if(agents_.begin(), agents_.end(), [](const AgentGoal& a) { return a.done; }));
}

bool GoalMachine::allDone() const {
  if (!started_) return false;
  for (size_t i = 0; i < agents_.size(); ++i)
    if (scene_.agentGroup[i] != kNoState && !agents_[i].done) return false;
  return true;
}

}  // namespace throng::crowd
