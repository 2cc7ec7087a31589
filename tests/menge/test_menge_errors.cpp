// Small hand-written inputs: generators, nav meshes and road maps against Menge's rules, and bad
// input answered with "FILE:LINE: what was expected" (or a warning for what is not supported).
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <doctest/doctest.h>

#include "core/error.h"
#include "menge/menge.h"

using namespace throng;
using namespace throng::menge;

namespace {

template <typename Body>
std::string errorOf(Body&& body) {
  try {
    body();
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The error (or warning) text is printed when the expected part is missing.
#define CHECK_CONTAINS(text, part)      \
  do {                                  \
    const std::string checked = (text); \
    INFO(checked);                      \
    CHECK(contains(checked, part));     \
  } while (0)

std::string experiment(const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<Experiment version=\"2.0\">\n"
         "  <AgentProfile name=\"p\"><Common r=\"0.2\"/></AgentProfile>\n" +
         body + "</Experiment>\n";
}

std::string group(const std::string& generator) {
  return "  <AgentGroup>\n    <ProfileSelector type=\"const\" name=\"p\"/>\n"
         "    <StateSelector type=\"const\" name=\"Walk\"/>\n" +
         generator + "  </AgentGroup>\n";
}

// Two triangles sharing the diagonal 0-2 of the unit square, outlined by four obstacles.
const char* kTwoTriangles =
    "4\n0 0\n1 0\n1 1\n0 1\n"
    "1\n0 2 0 1\n"
    "4\n0 1 0 1\n1 2 0 2\n2 3 1 3\n3 0 1 0\n"
    "tris\n2\n"
    "0.66 0.33\n3 0 1 2\n0 0 0\n1 0\n2 0 1\n"
    "0.33 0.66\n3 0 2 3\n0 0 0.5\n1 0\n2 2 3\n";

}  // namespace

TEST_CASE("menge: rect_grid rows follow anchor, offset and rotation") {
  const Scene scene = parseMengeScene(
      experiment(group("    <Generator type=\"rect_grid\" anchor_x=\"1\" anchor_y=\"2\" "
                       "offset_x=\"0.5\" offset_y=\"1\" count_x=\"3\" count_y=\"2\" "
                       "rotation=\"90\"/>\n")),
      "grid.xml");
  REQUIRE(scene.agents.size() == 6);
  // Agent 4 is (u=1, v=1): local (0.5, 1), rotated 90° to (-1, 0.5).
  CHECK(scene.agents[4].position.x == doctest::Approx(0.0).epsilon(1e-5));
  CHECK(scene.agents[4].position.y == doctest::Approx(2.5));
  CHECK(scene.groups[0].generators[0].agentCount == 6);
  CHECK(scene.warnings.empty());
}

TEST_CASE("menge: hex_lattice places Menge's whole rows, centred on the anchor") {
  const Scene scene = parseMengeScene(
      experiment(group("    <Generator type=\"hex_lattice\" anchor_x=\"0\" anchor_y=\"0\" "
                       "alignment=\"center\" row_direction=\"x\" density=\"1\" width=\"5\" "
                       "population=\"20\"/>\n")),
      "hex.xml");
  // Disk radius for 1 agent/m²: 1/sqrt(2·sqrt(3)); neighbours 2r apart, so 4 per long row
  // (5 m / 1.0746 m), bands of 4 + 3; 20 asked for -> three bands = 21 agents.
  const float r = 1.0f / std::sqrt(2.0f * std::sqrt(3.0f));
  REQUIRE(scene.agents.size() == 21);
  CHECK(scene.agents[0].position.x == doctest::Approx(-1.5 * 2 * r));
  CHECK(scene.agents[0].position.y == doctest::Approx(0.0));
  CHECK(scene.agents[4].position.x == doctest::Approx(-1.5 * 2 * r + r));  // short row
  CHECK(scene.agents[4].position.y == doctest::Approx(r * std::sqrt(3.0f)));
}

TEST_CASE("menge: malformed scenes name the file, the line and what was expected") {
  CHECK_CONTAINS(errorOf([] { parseMengeScene("<Experiment>\n<AgentGroup>\n", "cut.xml"); }),
                 "cut.xml:");
  CHECK_CONTAINS(errorOf([] { parseMengeScene("<Experiment>\n<AgentGroup>\n", "cut.xml"); }),
                 "malformed XML");
  CHECK_CONTAINS(errorOf([] { parseMengeScene("", "empty.xml"); }), "empty.xml:1:");
  CHECK_CONTAINS(errorOf([] { parseMengeScene("<BFSM/>", "wrong.xml"); }),
                 "wrong.xml:1: <BFSM>: expected <Experiment>");

  const std::string missing = errorOf([] {
    parseMengeScene(experiment(group("    <Generator type=\"rect_grid\" anchor_x=\"0\" "
                                     "anchor_y=\"0\" offset_x=\"1\" offset_y=\"1\" "
                                     "count_x=\"2\"/>\n")),
                    "missing.xml");
  });
  CHECK_CONTAINS(missing, "missing.xml:7: <Generator type=\"rect_grid\">: expected a 'count_y'");

  const std::string negative = errorOf([] {
    parseMengeScene(experiment(group("    <Generator type=\"rect_grid\" anchor_x=\"0\" "
                                     "anchor_y=\"0\" offset_x=\"1\" offset_y=\"1\" "
                                     "count_x=\"-3\" count_y=\"2\"/>\n")),
                    "negative.xml");
  });
  CHECK_CONTAINS(negative, "negative.xml:7:");
  CHECK_CONTAINS(negative, "expected 'count_x' in [0, 4000000], got -3");

  const std::string number = errorOf([] {
    parseMengeScene(experiment(group("    <Generator type=\"explicit\">\n"
                                     "      <Agent p_x=\"1\" p_y=\"nan\"/>\n"
                                     "    </Generator>\n")),
                    "nan.xml");
  });
  CHECK_CONTAINS(number, "nan.xml:8: <Agent>: expected 'p_y' to be a finite number");

  CHECK_CONTAINS(errorOf([] {
                   parseMengeScene(
                       "<Experiment>\n<AgentProfile name=\"b\" inherits=\"a\"/>\n</Experiment>",
                       "inherit.xml");
                 }),
                 "inherit.xml:2: <AgentProfile>: inherits 'a'");
  CHECK_CONTAINS(errorOf([] {
                   parseMengeScene(
                       "<Experiment>\n<AgentGroup>\n<ProfileSelector type=\"const\" "
                       "name=\"x\"/>\n<StateSelector type=\"const\" name=\"s\"/>\n"
                       "</AgentGroup>\n</Experiment>",
                       "profile.xml");
                 }),
                 "profile.xml:2: <AgentGroup>: profile 'x' is not defined");
}

TEST_CASE("menge: huge generators are refused before anything is allocated") {
  const std::string grid = errorOf([] {
    parseMengeScene(experiment(group("    <Generator type=\"rect_grid\" anchor_x=\"0\" "
                                     "anchor_y=\"0\" offset_x=\"1\" offset_y=\"1\" "
                                     "count_x=\"3000000\" count_y=\"3000000\"/>\n")),
                    "big.xml");
  });
  CHECK_CONTAINS(grid, "big.xml:7:");
  CHECK_CONTAINS(grid, "expected at most 4000000 agents");
  const std::string population = errorOf([] {
    parseMengeScene(experiment(group("    <Generator type=\"hex_lattice\" anchor_x=\"0\" "
                                     "anchor_y=\"0\" alignment=\"left\" row_direction=\"y\" "
                                     "density=\"2\" width=\"3\" population=\"99999999\"/>\n")),
                    "pop.xml");
  });
  CHECK_CONTAINS(population, "pop.xml:7:");
  CHECK_CONTAINS(population, "population");
  // A tiny density over a huge width is one enormous row.
  const std::string row = errorOf([] {
    parseMengeScene(experiment(group("    <Generator type=\"hex_lattice\" anchor_x=\"0\" "
                                     "anchor_y=\"0\" alignment=\"left\" row_direction=\"x\" "
                                     "density=\"0.001\" width=\"1e30\" population=\"1\"/>\n")),
                    "row.xml");
  });
  CHECK_CONTAINS(row, "row.xml:7:");
  CHECK_CONTAINS(row, "at most 4000000 agents");
}

TEST_CASE("menge: what is not supported is a warning naming the element and line") {
  const Scene scene =
      parseMengeScene(experiment("  <Bogus/>\n" +
                                 group("    <Generator type=\"nav_mesh\" file_name=\"x.nav\"/>\n") +
                                 "  <ObstacleSet type=\"explicit\" class=\"1\" colour=\"red\">\n"
                                 "    <Obstacle closed=\"0\"><Vertex p_x=\"0\" p_y=\"0\"/>"
                                 "<Vertex p_x=\"1\" p_y=\"0\"/></Obstacle>\n"
                                 "  </ObstacleSet>\n"),
                      "warn.xml");
  REQUIRE(scene.warnings.size() == 3);
  CHECK_CONTAINS(scene.warnings[0], "warn.xml:4: <Bogus>: element not supported");
  CHECK_CONTAINS(scene.warnings[1], "warn.xml:8: <Generator type=\"nav_mesh\">");
  CHECK_CONTAINS(scene.warnings[2],
                 "warn.xml:10: <ObstacleSet type=\"explicit\">: attribute "
                 "'colour'");
  CHECK(scene.agents.empty());
  REQUIRE(scene.obstacleSets.size() == 1);
  CHECK_FALSE(scene.obstacleSets[0].obstacles[0].closed);

  const Behavior behavior = parseMengeBehavior(
      "<BFSM>\n<State name=\"A\">\n<GoalSelector type=\"teleport\"/>\n"
      "<VelComponent type=\"vel_field\" file_name=\"f\"/>\n</State>\n"
      "<Transition from=\"A\" to=\"A\"><Condition type=\"AABB\"/></Transition>\n"
      "<EventSystem/>\n</BFSM>",
      "b.xml");
  REQUIRE(behavior.warnings.size() == 4);
  CHECK_CONTAINS(behavior.warnings[0], "b.xml:3: <GoalSelector type=\"teleport\">");
  CHECK_CONTAINS(behavior.warnings[1], "b.xml:4: <VelComponent type=\"vel_field\">");
  CHECK_CONTAINS(behavior.warnings[2], "b.xml:6: <Condition type=\"AABB\">");
  CHECK_CONTAINS(behavior.warnings[3], "b.xml:7: <EventSystem>");
  CHECK(behavior.states[0].goalSelector.kind == GoalSelector::Kind::Unsupported);
  CHECK(behavior.transitions[0].condition.kind == Condition::Kind::Unsupported);
}

TEST_CASE("menge: behaviour goals, selectors and transitions are checked against each other") {
  const Behavior b = parseMengeBehavior(
      "<BFSM>\n<GoalSet id=\"3\">\n"
      "<Goal type=\"point\" id=\"0\" x=\"1\" y=\"2\"/>\n"
      "<Goal type=\"circle\" id=\"1\" x=\"0\" y=\"0\" radius=\"2\" weight=\"0.5\"/>\n"
      "<Goal type=\"OBB\" id=\"2\" x=\"0\" y=\"0\" width=\"2\" height=\"1\" angle=\"30\"/>\n"
      "</GoalSet>\n"
      "<State name=\"Go\"><GoalSelector type=\"explicit\" goal_set=\"3\" goal=\"2\"/>"
      "<VelComponent type=\"goal\"/></State>\n"
      "<State name=\"Near\"><GoalSelector type=\"nearest\" goal_set=\"3\"/></State>\n"
      "<State name=\"End\" final=\"1\"/>\n"
      "<Transition from=\"Go, Near\" to=\"End\"><Condition type=\"timer\" dist=\"c\" "
      "value=\"3\"/></Transition>\n</BFSM>",
      "goals.xml");
  CHECK(b.warnings.empty());
  REQUIRE(b.goalSets.size() == 1);
  REQUIRE(b.goalSets[0].goals.size() == 3);
  CHECK(b.goalSets[0].goals[1].kind == Goal::Kind::Circle);
  CHECK(b.goalSets[0].goals[1].weight == doctest::Approx(0.5));
  CHECK(b.goalSets[0].goals[2].angle == doctest::Approx(30));
  REQUIRE(b.transitions.size() == 2);  // one per state of the `from` list
  CHECK(b.transitions[1].fromIndex == 1);
  CHECK(b.transitions[1].targets[0].stateIndex == 2);
  CHECK(b.transitions[0].condition.duration.value == doctest::Approx(3));

  CHECK_CONTAINS(errorOf([] {
                   parseMengeBehavior(
                       "<BFSM>\n<GoalSet id=\"0\"/>\n<State name=\"A\">\n"
                       "<GoalSelector type=\"explicit\" goal_set=\"0\" "
                       "goal=\"7\"/></State>\n</BFSM>",
                       "g.xml");
                 }),
                 "g.xml:4: <GoalSelector>: goal 7 is not in goal set 0");
  CHECK_CONTAINS(errorOf([] {
                   parseMengeBehavior(
                       "<BFSM>\n<State name=\"A\"/>\n<Transition from=\"A\" "
                       "to=\"B\"><Condition type=\"auto\"/></Transition>\n</BFSM>",
                       "t.xml");
                 }),
                 "t.xml:3: <Transition>: state 'B' is not defined");
  CHECK_CONTAINS(errorOf([] {
                   parseMengeBehavior(
                       "<BFSM>\n<GoalSet id=\"0\">\n<Goal type=\"AABB\" id=\"0\" "
                       "min_x=\"2\" min_y=\"0\" max_x=\"1\" max_y=\"1\"/>\n"
                       "</GoalSet>\n</BFSM>",
                       "box.xml");
                 }),
                 "box.xml:3: <Goal type=\"AABB\">: expected min_x <= max_x");
}

TEST_CASE("menge: a nav mesh's polygons, planes and adjacency") {
  const NavMesh mesh = parseNavMesh(kTwoTriangles, "two.nav");
  CHECK(mesh.vertices.size() == 4);
  REQUIRE(mesh.nodes.size() == 2);
  CHECK(mesh.nodes[1].polygon == std::vector<uint32_t>{0, 2, 3});
  CHECK(mesh.nodes[1].plane.z == doctest::Approx(0.5));
  CHECK(mesh.nodes[0].neighbors == std::vector<uint32_t>{1});
  CHECK(mesh.nodes[1].neighbors == std::vector<uint32_t>{0});
  CHECK(mesh.obstacles[3].next == 0);
  REQUIRE(mesh.groups.size() == 1);
  CHECK(mesh.groups[0].name == "tris");
}

TEST_CASE("menge: bad nav meshes and road maps name the line and what was expected") {
  std::string badVertex = kTwoTriangles;
  badVertex.replace(badVertex.find("3 0 2 3"), 7, "3 0 2 9");
  CHECK_CONTAINS(errorOf([&] { parseNavMesh(badVertex, "v.nav"); }),
                 "v.nav:21: expected a node polygon's vertex in [0, 4), got 9");
  std::string badNode = kTwoTriangles;
  badNode.replace(badNode.find("0 2 0 1"), 7, "0 2 0 5");
  CHECK_CONTAINS(errorOf([&] { parseNavMesh(badNode, "n.nav"); }),
                 "n.nav:7: edge 0 names node 5, expected a node index < 2");
  CHECK_CONTAINS(errorOf([] { parseNavMesh("999999999\n0 0\n", "huge.nav"); }),
                 "huge.nav:1: expected the vertex count that the rest of the file can hold");
  CHECK_CONTAINS(errorOf([] { parseNavMesh("-2\n", "neg.nav"); }),
                 "neg.nav:1: expected the vertex count >= 0");
  CHECK_CONTAINS(errorOf([] { parseNavMesh("2\n0 0\n1      ", "cut.nav"); }),
                 "cut.nav:3: expected a vertex y, found the end of the file");

  const RoadMap map = parseRoadMap("3\n2 0 0\n1 1 0\n1 0 1\n2\n0 1\n0 2\n", "map.txt");
  CHECK(map.vertices.size() == 3);
  CHECK(map.edges.size() == 2);
  CHECK_CONTAINS(errorOf([] { parseRoadMap("2\n2 0 0\n1 1 0\n1\n0 1\n", "deg.txt"); }),
                 "deg.txt:2: vertex 0's degree does not match");
  CHECK_CONTAINS(errorOf([] { parseRoadMap("2\n1 0 0\n1 1 0\n1\n0 4\n", "idx.txt"); }),
                 "idx.txt:5: expected an edge's second vertex in [0, 2), got 4");
}

TEST_CASE("menge: a project resolves its files and checks initial states") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("throng_menge_" + std::to_string(::getpid()));
  fs::create_directories(dir / "sub");
  const auto write = [&](const fs::path& path, const std::string& text) {
    std::ofstream(dir / path) << text;
  };
  write("p.xml", "<Project scene=\"sub/s.xml\" behavior=\"sub/b.xml\" model=\"orca\" x=\"1\"/>");
  write("sub/s.xml", experiment(group("    <Generator type=\"explicit\"><Agent p_x=\"0\" "
                                      "p_y=\"0\"/></Generator>\n")));
  write("sub/b.xml",
        "<BFSM>\n<State name=\"Walk\"><VelComponent type=\"nav_mesh\" "
        "file_name=\"m.nav\"/></State>\n</BFSM>");
  write("sub/m.nav", kTwoTriangles);
  const MengeScenario s = readMengeProject(dir / "p.xml");
  CHECK(s.scene.agents.size() == 1);
  REQUIRE(s.navMeshes.size() == 1);
  CHECK(s.navMeshes[0].nodes.size() == 2);
  REQUIRE(s.warnings.size() == 1);  // the unknown project attribute
  CHECK_CONTAINS(s.warnings[0], "p.xml:1: <Project>: attribute 'x'");

  write("sub/b.xml", "<BFSM>\n<State name=\"Run\"/>\n</BFSM>");
  CHECK_CONTAINS(errorOf([&] { readMengeProject(dir / "p.xml"); }),
                 "s.xml:4: <AgentGroup>: initial state 'Walk' is not a state of");
  fs::remove(dir / "sub/b.xml");
  CHECK_CONTAINS(errorOf([&] { readMengeProject(dir / "p.xml"); }), "b.xml");
  fs::remove_all(dir);
}
