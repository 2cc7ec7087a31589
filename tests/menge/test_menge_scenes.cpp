// The five Menge example scenes in ../shared/data/scenes/menge, read end to end. Expected counts
// come from the files themselves (e.g. `grep -c '<Agent ' tradeshowS.xml` = 1025, the group
// names and node counts of tradeshow.nav), not from this reader.
#include <algorithm>
#include <string>

#include <doctest/doctest.h>

#include "menge/menge.h"
#include "test_support.h"

using namespace throng;
using namespace throng::menge;

namespace {

constexpr const char* kMengeDir = "scenes/menge";

MengeScenario readShared(const std::string& name) {
  return readMengeProject(test::sharedDataDir() / kMengeDir / (name + ".xml"));
}

size_t countGenerators(const Scene& scene, Generator::Kind kind) {
  size_t n = 0;
  for (const AgentGroup& group : scene.groups) {
    n += std::count_if(group.generators.begin(), group.generators.end(),
                       [&](const Generator& g) { return g.kind == kind; });
  }
  return n;
}

}  // namespace

TEST_CASE("menge: circle has 100 explicit agents walking to their mirrored position") {
  if (!test::haveSharedData(kMengeDir)) return;
  const MengeScenario s = readShared("circle");
  CHECK(s.model == "orca");
  REQUIRE(s.scene.agents.size() == 100);
  CHECK(countGenerators(s.scene, Generator::Kind::Explicit) == 1);
  CHECK(s.scene.agents[0].position.x == doctest::Approx(8.555987));
  CHECK(s.scene.agents[99].position.y == doctest::Approx(-0.537235));
  REQUIRE(s.scene.profiles.size() == 1);
  const AgentProfile& p = s.scene.profiles[0];
  CHECK(p.radius == doctest::Approx(0.18));
  CHECK(p.prefSpeed == doctest::Approx(1.3));
  CHECK(p.maxNeighbors == 10);
  REQUIRE(p.distributions.size() == 1);  // <Property name="r" dist="u" min max>
  CHECK(p.distributions[0].name == "r");
  CHECK(p.distributions[0].distribution.kind == Distribution::Kind::Uniform);
  CHECK(p.distributions[0].distribution.max == doctest::Approx(0.25));
  CHECK(p.distributions[0].distribution.seed == 2);
  REQUIRE(s.behavior.states.size() == 2);
  CHECK(s.behavior.states[0].goalSelector.kind == GoalSelector::Kind::Mirror);
  CHECK(s.behavior.states[0].goalSelector.mirrorX);
  CHECK(s.behavior.states[1].final);
  REQUIRE(s.behavior.transitions.size() == 1);
  CHECK(s.behavior.transitions[0].condition.kind == Condition::Kind::GoalReached);
  CHECK(s.behavior.transitions[0].condition.distance == doctest::Approx(0.1));
  CHECK(s.scene.groups[0].state == "Walk");
  CHECK(s.warnings.empty());
  // The pedestrian models' parameter blocks are listed, not warned about.
  CHECK(std::binary_search(s.scene.ignoredElements.begin(), s.scene.ignoredElements.end(),
                           std::string("Helbing")));
}

TEST_CASE("menge: 4square's four 5x5 grids, inherited profiles and square obstacles") {
  if (!test::haveSharedData(kMengeDir)) return;
  const MengeScenario s = readShared("4square");
  CHECK(s.scene.agents.size() == 100);
  CHECK(countGenerators(s.scene, Generator::Kind::RectGrid) == 4);
  const Generator& g = s.scene.groups[1].generators[0];
  CHECK(g.hasDisplacement);
  CHECK(g.displacement.kind == Distribution::Kind::Uniform);
  // Group 2's grid: anchor (7.3, -7.3), offset (1.333, -1.333); agent (u=4, v=4) is the last.
  const glm::vec2 last = s.scene.agents[g.firstAgent + 24].position;
  CHECK(last.x == doctest::Approx(7.3 + 4 * 1.333));
  CHECK(last.y == doctest::Approx(-7.3 - 4 * 1.333));
  REQUIRE(s.scene.profiles.size() == 4);
  const AgentProfile& group4 = s.scene.profiles[3];
  CHECK(group4.inherits == "group1");
  CHECK(group4.radius == doctest::Approx(0.35));
  CHECK(group4.prefSpeed == doctest::Approx(0.75));  // constant <Property>
  CHECK(group4.maxSpeed == doctest::Approx(2.0));    // inherited
  CHECK(group4.agentClass == 4);
  CHECK(s.scene.groups[3].profileIndex == 3);
  REQUIRE(s.scene.obstacleSets.size() == 1);
  CHECK(s.scene.obstacleSets[0].obstacles.size() == 4);
  CHECK(s.scene.obstacleSets[0].obstacles[0].closed);
  CHECK(s.scene.obstacleSets[0].obstacles[0].vertices.size() == 4);
  CHECK(s.behavior.transitions[0].condition.distance == doctest::Approx(0.05));
}

TEST_CASE("menge: bottleneck walks a road map to an AABB goal") {
  if (!test::haveSharedData(kMengeDir)) return;
  const MengeScenario s = readShared("bottleneck");
  CHECK(s.scene.agents.size() == 5);
  REQUIRE(s.behavior.goalSets.size() == 1);
  const Goal& goal = s.behavior.goalSets[0].goals.at(0);
  CHECK(goal.kind == Goal::Kind::AABB);
  CHECK(goal.min.x == doctest::Approx(-20));
  CHECK(goal.max.y == doctest::Approx(8));
  const State& walk = s.behavior.states.at(0);
  CHECK(walk.goalSelector.kind == GoalSelector::Kind::Explicit);
  CHECK(walk.velocity.kind == VelocityComponent::Kind::RoadMap);
  CHECK(walk.velocity.file.filename() == "bottleneckMap.txt");
  CHECK(s.behavior.states.at(1).velocity.kind == VelocityComponent::Kind::Zero);
  REQUIRE(s.roadMaps.size() == 1);
  CHECK(s.roadMaps[0].vertices.size() == 6);
  CHECK(s.roadMaps[0].edges.size() == 10);
  CHECK(s.scene.obstacleSets.at(0).obstacles.size() == 2);
}

TEST_CASE("menge: stadium's nav mesh: three node groups, 22 nodes, obstacle set from the mesh") {
  if (!test::haveSharedData(kMengeDir)) return;
  const MengeScenario s = readShared("stadium");
  CHECK(s.scene.agents.size() == 90);  // two 5x9 grids in one group
  REQUIRE(s.scene.groups.size() == 1);
  CHECK(s.scene.groups[0].generators.size() == 2);
  REQUIRE(s.scene.obstacleSets.size() == 1);
  CHECK(s.scene.obstacleSets[0].kind == ObstacleSet::Kind::NavMesh);
  CHECK(s.behavior.states[0].goalSelector.kind == GoalSelector::Kind::NearestNavMesh);
  REQUIRE(s.navMeshes.size() == 1);  // named three times, read once
  const NavMesh& mesh = s.navMeshes[0];
  CHECK(mesh.vertices.size() == 88);
  CHECK(mesh.edges.size() == 21);
  CHECK(mesh.obstacles.size() == 88);
  REQUIRE(mesh.groups.size() == 3);
  CHECK(mesh.groups[0].name == "stairGrp");
  CHECK(mesh.groups[2].nodeCount == 20);
  REQUIRE(mesh.nodes.size() == 22);
  CHECK(mesh.nodes[0].polygon.size() == 4);
  CHECK(mesh.nodes[0].plane.y == doctest::Approx(0.6745));
  CHECK(mesh.nodes[0].edges.size() == 21);
  CHECK(mesh.nodes[0].obstacles.size() == 68);
  // The stairs touch the floor (edge 0) and every row (edges 1..20).
  CHECK(mesh.nodes[0].neighbors.size() == 21);
  CHECK(mesh.nodes[1].neighbors == std::vector<uint32_t>{0});
}

TEST_CASE("menge: tradeshow: 1025 agents, 40 goals, a probabilistic transition, timers") {
  if (!test::haveSharedData(kMengeDir)) return;
  const MengeScenario s = readShared("tradeshow");
  CHECK(s.scene.agents.size() == 1025);
  REQUIRE(s.scene.obstacleSets.size() == 1);
  CHECK(s.scene.obstacleSets[0].obstacles.size() == 103);
  REQUIRE(s.behavior.goalSets.size() == 1);
  const auto& goals = s.behavior.goalSets[0].goals;
  CHECK(goals.size() == 40);
  CHECK(std::all_of(goals.begin(), goals.end(), [](const Goal& g) {
    return g.kind == Goal::Kind::AABB && g.capacity == 10000.0f && g.weight == 1.0f;
  }));
  REQUIRE(s.behavior.states.size() == 5);
  const State& walk = s.behavior.states[0];
  CHECK(walk.goalSelector.kind == GoalSelector::Kind::Random);
  CHECK(walk.goalSelector.perAgent);
  CHECK(walk.velocity.kind == VelocityComponent::Kind::NavMesh);
  CHECK(walk.velocity.headingThreshold == doctest::Approx(5));
  REQUIRE(s.behavior.transitions.size() == 5);
  const Transition& timer = s.behavior.transitions[1];
  CHECK(timer.condition.kind == Condition::Kind::Timer);
  CHECK(timer.condition.duration.kind == Distribution::Kind::Uniform);
  CHECK(timer.condition.duration.min == doctest::Approx(2));
  CHECK(timer.condition.duration.max == doctest::Approx(4));
  CHECK(timer.condition.perAgent);
  const Transition& decide = s.behavior.transitions[2];
  CHECK(decide.condition.kind == Condition::Kind::Auto);
  REQUIRE(decide.targets.size() == 2);
  CHECK(s.behavior.states[decide.targets[1].stateIndex].name == "Angry");
  // The <Action> elements of Walk and Arrive are not supported: one warning each, with a line.
  const auto actions = std::count_if(s.warnings.begin(), s.warnings.end(), [](const auto& w) {
    return w.find("tradeshowB.xml:") != std::string::npos &&
           w.find("<Action type=\"offset_property\">") != std::string::npos;
  });
  CHECK(actions == 2);
  REQUIRE(s.navMeshes.size() == 1);
  CHECK(s.navMeshes[0].vertices.size() == 470);
  CHECK(s.navMeshes[0].groups.size() == 1);
  CHECK(s.navMeshes[0].nodes.size() == 338);
}
