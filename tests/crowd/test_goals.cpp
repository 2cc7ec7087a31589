#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/error.h"
#include "crowd/goals.h"
#include "menge/menge.h"

using namespace throng;
using crowd::Goal;
using crowd::GoalChoice;
using crowd::GoalState;

namespace {

// One group, one state machine, goals in set 0.
crowd::GoalScene sceneOf(std::vector<Goal> goals, std::vector<GoalState> states, size_t agents) {
  crowd::GoalScene scene;
  scene.goalSets = {crowd::GoalSet{std::move(goals)}};
  scene.groups = {crowd::GoalBehavior{std::move(states), 0, 1.3f}};
  scene.agentGroup.assign(agents, 0);
  return scene;
}

GoalState state(GoalChoice::Kind kind, uint32_t goal, GoalState::Arrival arrival,
                uint32_t next = crowd::kNoState, float wait = 0.0f) {
  GoalState s;
  s.choice.kind = kind;
  s.choice.goal = goal;
  s.onArrival = arrival;
  s.next = next;
  s.waitSeconds = wait;
  s.reach = 0.5f;
  return s;
}

}  // namespace

TEST_CASE("goals: distance, closest point and samples of every shape") {
  const std::vector<Goal> goals = {
      crowd::pointGoal({1, 2}), crowd::circleGoal({0, 0}, 2.0f), crowd::boxGoal({-1, -2}, {3, 4}),
      crowd::orientedBoxGoal({0, 0}, {2.0f, 0.5f}, 3.14159265f / 2.0f)};
  CHECK(crowd::goalDistance(goals[0], {4, 6}) == doctest::Approx(5.0f));
  CHECK(crowd::goalDistance(goals[1], {0, 5}) == doctest::Approx(3.0f));
  CHECK(crowd::goalDistance(goals[1], {0.5f, 0.5f}) == 0.0f);
  CHECK(crowd::goalDistance(goals[2], {6, 8}) == doctest::Approx(5.0f));
  // The oriented box turned by 90°: long along z.
  CHECK(crowd::goalDistance(goals[3], {0.0f, 1.8f}) == doctest::Approx(0.0f));
  CHECK(crowd::goalDistance(goals[3], {1.5f, 0.0f}) == doctest::Approx(1.0f));
  for (const Goal& g : goals) {
    CHECK(crowd::validateGoal(g).empty());
    for (glm::vec2 p : {glm::vec2(7, -3), glm::vec2(0.2f, 0.1f), glm::vec2(-4, 9)}) {
      const glm::vec2 c = crowd::closestGoalPoint(g, p);
      CHECK(glm::distance(c, p) == doctest::Approx(crowd::goalDistance(g, p)).epsilon(1e-4));
      CHECK(crowd::goalDistance(g, c) < 1e-4f);
    }
    std::set<std::pair<float, float>> distinct;
    for (uint32_t agent = 0; agent < 100; ++agent) {
      const glm::vec2 s = crowd::sampleGoalPoint(g, agent, 1, 7);
      CHECK(crowd::goalDistance(g, s) < 1e-4f);
      CHECK(s == crowd::sampleGoalPoint(g, agent, 1, 7));  // deterministic
      distinct.insert({s.x, s.y});
    }
    CHECK(distinct.size() == (g.shape == Goal::Shape::Point ? 1u : 100u));
  }
  Goal bad = crowd::circleGoal({0, 0}, -1.0f);
  CHECK(crowd::validateGoal(bad).size() == 1);
}

TEST_CASE("goals: Menge goals become regions, the OBB pivoting on its corner") {
  menge::Goal obb;
  obb.kind = menge::Goal::Kind::OBB;
  obb.position = {1, 1};
  obb.width = 2.0f;
  obb.height = 1.0f;
  obb.angle = 90.0f;
  const Goal g = crowd::goalFromMenge(obb);
  // Corners: pivot, pivot + R(w, 0) = (1, 3), pivot + R(0, h) = (0, 1).
  for (glm::vec2 corner : {glm::vec2(1, 1), glm::vec2(1, 3), glm::vec2(0, 1), glm::vec2(0, 3)})
    CHECK(crowd::goalDistance(g, corner) < 1e-5f);
  CHECK(crowd::goalDistance(g, {2, 2}) == doctest::Approx(1.0f));
  menge::Goal box;
  box.kind = menge::Goal::Kind::AABB;
  box.min = {-7.5f, -9.5f};
  box.max = {7.5f, -2.5f};
  CHECK(crowd::goalDistance(crowd::goalFromMenge(box), {0, 0}) == doctest::Approx(2.5f));
}

TEST_CASE("goals: selection explicit, nearest, random by weight and shared") {
  std::vector<Goal> goals = {crowd::pointGoal({0, 10}), crowd::pointGoal({10, 0}),
                             crowd::pointGoal({-10, 0})};
  const std::vector<glm::vec2> positions = {{9, 1}, {-8, 0}, {0, 7}, {1, 1}};
  auto targets = [&](GoalChoice::Kind kind, uint32_t seed) {
    crowd::GoalScene scene = sceneOf(goals, {state(kind, 2, GoalState::Arrival::Stop)}, 4);
    scene.seed = seed;
    crowd::GoalMachine machine(scene, positions.size());
    CHECK(machine.evaluate(positions, 0.0).size() == positions.size());
    std::vector<glm::vec2> out;
    for (const crowd::AgentGoal& a : machine.agents()) out.push_back(a.target);
    return out;
  };
  for (glm::vec2 t : targets(GoalChoice::Kind::Explicit, 1)) CHECK(t == glm::vec2(-10, 0));
  const std::vector<glm::vec2> nearest = targets(GoalChoice::Kind::Nearest, 1);
  CHECK(nearest[0] == glm::vec2(10, 0));
  CHECK(nearest[1] == glm::vec2(-10, 0));
  CHECK(nearest[2] == glm::vec2(0, 10));
  for (uint32_t seed = 1; seed < 6; ++seed) {
    const std::vector<glm::vec2> shared = targets(GoalChoice::Kind::Shared, seed);
    CHECK(std::all_of(shared.begin(), shared.end(), [&](glm::vec2 t) { return t == shared[0]; }));
  }
  CHECK(targets(GoalChoice::Kind::Random, 3) == targets(GoalChoice::Kind::Random, 3));
  // Weights: goal 1 never, goal 2 about three times as often as goal 0.
  goals[1].weight = 0.0f;
  goals[2].weight = 3.0f;
  crowd::GoalScene scene =
      sceneOf(goals, {state(GoalChoice::Kind::Random, 0, GoalState::Arrival::Stop)}, 2000);
  crowd::GoalMachine machine(scene, 2000);
  machine.evaluate(std::vector<glm::vec2>(2000, glm::vec2(0.0f)), 0.0);
  uint32_t counts[3] = {};
  for (const crowd::AgentGoal& a : machine.agents()) ++counts[a.goal];
  CHECK(counts[1] == 0);
  CHECK(counts[2] > 2 * counts[0]);
  CHECK(counts[2] < 4 * counts[0]);
}

TEST_CASE("goals: wait on arrival, then the next state; final states stop") {
  crowd::GoalScene scene =
      sceneOf({crowd::pointGoal({5, 0}), crowd::pointGoal({10, 0})},
              {state(GoalChoice::Kind::Explicit, 0, GoalState::Arrival::Wait, 1, 2.0f),
               state(GoalChoice::Kind::Explicit, 1, GoalState::Arrival::Stop)},
              2);
  scene.agentGroup[1] = crowd::kNoState;  // no goals: left alone
  crowd::GoalMachine m(scene, 2);
  using V = std::vector<glm::vec2>;
  CHECK(m.evaluate(V{{0, 0}, {3, 3}}, 0.0) == std::vector<uint32_t>{0});
  CHECK(m.paths()[0] == V{{0, 0}, {5, 0}});  // no nav structure: the straight line
  CHECK(m.paths()[1].empty());
  CHECK(m.evaluate(V{{3, 0}, {3, 3}}, 1.0).empty());
  CHECK(m.agents()[0].reachedAt < 0.0);
  CHECK(m.evaluate(V{{4.8f, 0}, {3, 3}}, 1.5).empty());  // reached: the wait starts
  CHECK(m.agents()[0].reachedAt == 1.5);
  CHECK(m.evaluate(V{{5, 0}, {3, 3}}, 3.0).empty());  // waited 1.5 of 2 s
  CHECK(m.agents()[0].state == 0);
  CHECK(m.evaluate(V{{5, 0}, {3, 3}}, 3.5) == std::vector<uint32_t>{0});
  CHECK(m.agents()[0].state == 1);
  CHECK(m.paths()[0] == V{{5, 0}, {10, 0}});
  CHECK_FALSE(m.allDone());
  CHECK(m.evaluate(V{{9.9f, 0}, {3, 3}}, 8.0).empty());
  CHECK(m.agents()[0].done);
  CHECK(m.agentsAtGoal() == 1);
  CHECK(m.allDone());
  CHECK(m.plans() == 2);
}

TEST_CASE("goals: on arrival the next goal of the set, and a timer leaves a state unreached") {
  const std::vector<Goal> goals = {crowd::pointGoal({0, 0}), crowd::pointGoal({4, 0}),
                                   crowd::boxGoal({4, 4}, {6, 6})};
  crowd::GoalScene scene =
      sceneOf(goals, {state(GoalChoice::Kind::Explicit, 1, GoalState::Arrival::NextGoal, 1)}, 1);
  scene.groups[0].states.push_back(state(GoalChoice::Kind::Identity, 0, GoalState::Arrival::Stop));
  scene.groups[0].states[0].leaveAfter = 20.0f;
  crowd::GoalMachine m(scene, 1);
  using V = std::vector<glm::vec2>;
  m.evaluate(V{{1, 0}}, 0.0);
  CHECK(m.agents()[0].goal == 1);
  CHECK(m.evaluate(V{{4, 0}}, 2.0).size() == 1);
  CHECK(m.agents()[0].goal == 2);
  CHECK(m.agents()[0].target == glm::vec2(4, 4));  // the box's closest point
  CHECK(m.evaluate(V{{4.5f, 4.5f}}, 4.0).size() == 1);
  CHECK(m.agents()[0].goal == 0);
  CHECK(m.evaluate(V{{2, 0}}, 10.0).empty());
  CHECK(m.agents()[0].state == 0);
  // 20 s in the state: the timer moves it on, unreached, to stand where it is.
  CHECK(m.evaluate(V{{2, 1}}, 20.0).size() == 1);
  CHECK(m.agents()[0].state == 1);
  CHECK(m.agents()[0].target == glm::vec2(2, 1));
  m.evaluate(V{{2, 1}}, 21.0);
  CHECK(m.allDone());
}

TEST_CASE("goals: invalid scenes are refused with the reason") {
  crowd::GoalScene scene =
      sceneOf({crowd::pointGoal({0, 0})},
              {state(GoalChoice::Kind::Explicit, 3, GoalState::Arrival::Wait, 5)}, 2);
  const std::vector<std::string> problems = crowd::validateGoalScene(scene, 2);
  REQUIRE(problems.size() == 2);
  CHECK(problems[0] == "group 0 state 0: next state 5 of 1");
  CHECK(problems[1] == "group 0 state 0: goal 3 of 1");
  CHECK_THROWS_WITH_AS(crowd::GoalMachine(scene, 2), "goals: group 0 state 0: next state 5 of 1",
                       Error);
  scene = sceneOf({crowd::pointGoal({0, 0})},
                  {state(GoalChoice::Kind::Explicit, 0, GoalState::Arrival::Stop)}, 2);
  CHECK(crowd::validateGoalScene(scene, 3).front() == "2 agent groups given for 3 agents");
  scene.agentGroup[1] = 4;
  CHECK(crowd::validateGoalScene(scene, 2).front() == "agent 1 is in group 4 of 1");
}
