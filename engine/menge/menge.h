#pragma once
// Menge scenarios (https://github.com/MengeCrowdSim/Menge) read into plain data: no simulation,
// no GPU. A Menge project XML names a scene file (the Experiment: agent profiles, agent groups
// with generators, obstacle sets) and a behaviour file (the BFSM: goal sets, states, transitions);
// velocity components and obstacle sets may point at a navigation mesh (.nav) or a road map
// (.txt). docs/formats.md "Menge scenarios" lists the supported subset.
//
// Every reader:
//   * throws throng::Error "FILE:LINE: what was expected" for malformed input (broken XML, a
//     missing or unparsable required attribute, a negative or oversized count, an index out of
//     range, an unknown profile or state name);
//   * records anything it does not understand (an unknown element, attribute or type) as a
//     warning "FILE:LINE: <Element ...>: what was skipped" instead of dropping it silently;
//   * bounds every allocation: at most kMaxAgents generated agents per scene, kMaxFileBytes per
//     file, and a nav mesh / road map count is checked against the bytes left in its file before
//     anything is reserved.
// Positions are Menge's 2D ground-plane coordinates (x, y) in metres, unchanged.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace throng::menge {

inline constexpr size_t kMaxAgents = 4'000'000;         // per scene, all generators together
inline constexpr uintmax_t kMaxFileBytes = 256u << 20;  // per file read

// A value drawn per agent (Menge's `dist` attribute family): "c" value, "u" min..max, "n" mean
// and standard deviation. Readers keep the description; nothing is sampled here.
struct Distribution {
  enum class Kind { Constant, Uniform, Normal };
  Kind kind = Kind::Constant;
  float value = 0.0f;  // Constant
  float min = 0.0f;    // Uniform
  float max = 0.0f;
  float mean = 0.0f;  // Normal
  float stddev = 0.0f;
  bool hasSeed = false;  // `seed` attribute present
  uint32_t seed = 0;
};

// ---- Scene (the Experiment element of *S.xml) ----

// <AgentProfile name inherits> with its <Common> attributes. Values start at Menge's agent
// defaults, then the inherited profile's, then this profile's own attributes.
struct PropertyDistribution {
  std::string name;  // the Common attribute it replaces: "r", "pref_speed", ...
  Distribution distribution;
};
struct AgentProfile {
  std::string name;
  std::string inherits;                // empty: none
  float radius = 0.19f;                // r, metres
  float prefSpeed = 1.34f;             // pref_speed, m/s
  float maxSpeed = 2.5f;               // max_speed, m/s
  float maxAccel = 2.0f;               // max_accel, m/s²
  float maxAngleVel = 360.0f;          // max_angle_vel, degrees/s
  float neighborDist = 5.0f;           // neighbor_dist, metres
  uint32_t maxNeighbors = 10;          // max_neighbors
  uint32_t obstacleSet = 0xFFFFFFFFu;  // obstacleSet: bit mask of obstacle classes it sees
  uint32_t agentClass = 0;             // class
  float priority = 0.0f;
  // <Property name dist ...> children of <Common>: a constant one already set the field above;
  // uniform and normal ones are listed here (the field keeps the attribute's value).
  std::vector<PropertyDistribution> distributions;
  int line = 0;  // of the <AgentProfile> element
};

// One <Generator> of a group, as written; its agents are expanded into Scene::agents.
struct Generator {
  enum class Kind { Explicit, RectGrid, HexLattice };
  Kind kind = Kind::Explicit;
  // rect_grid: agent (u, v), u < countX, v < countY, at anchor + R(rotation)·(u·offset.x,
  // v·offset.y), row by row.
  glm::vec2 anchor{0.0f};
  glm::vec2 offset{0.0f};
  uint32_t countX = 0, countY = 0;
  // hex_lattice: rows of agents at the spacing that gives `density` agents/m², `width` metres
  // wide, `population` agents asked for (Menge rounds up to whole rows: see populationPlaced),
  // rows along x or y, the anchor at the lattice's left, centre or right.
  enum class Alignment { Center, Left, Right };
  enum class RowDirection { X, Y };
  Alignment alignment = Alignment::Center;
  RowDirection rowDirection = RowDirection::X;
  float density = 0.0f;
  float width = 0.0f;
  uint32_t population = 0;
  float rotation = 0.0f;  // degrees, counter-clockwise (rect_grid and hex_lattice)
  // Random displacement of each generated position (displace_dist, displace_*); the positions in
  // Scene::agents are the undisplaced ones.
  bool hasDisplacement = false;
  Distribution displacement;
  size_t firstAgent = 0;  // index into Scene::agents
  size_t agentCount = 0;  // agents this generator placed
  int line = 0;
};

// <AgentGroup>: which profile and initial state its agents get, and its generators.
struct AgentGroup {
  std::string profile;    // <ProfileSelector type="const" name>; empty when unsupported (warned)
  int profileIndex = -1;  // into Scene::profiles, -1 when `profile` is empty
  std::string state;      // <StateSelector type="const" name>: a BFSM state name
  std::vector<Generator> generators;
  int line = 0;
};

struct AgentStart {
  glm::vec2 position{0.0f};
  uint32_t group = 0;  // into Scene::groups (profile and initial state)
};

// <Obstacle closed> with its <Vertex p_x p_y> list (closed: the last vertex joins the first).
struct Obstacle {
  std::vector<glm::vec2> vertices;
  bool closed = true;
  int line = 0;
};

// <ObstacleSet type="explicit"|"nav_mesh" class>.
struct ObstacleSet {
  enum class Kind { Explicit, NavMesh };
  Kind kind = Kind::Explicit;
  uint32_t obstacleClass = 1;       // class: matched against a profile's obstacleSet mask
  std::vector<Obstacle> obstacles;  // Explicit
  std::filesystem::path navMesh;    // NavMesh: file_name, resolved against the scene's folder
  int line = 0;
};

struct Scene {
  std::filesystem::path source;
  std::string version;    // Experiment's version attribute
  float timeStep = 0.1f;  // <Common time_step>, seconds
  std::vector<AgentProfile> profiles;
  std::vector<AgentGroup> groups;
  std::vector<AgentStart> agents;  // every generated agent, group by group, in file order
  std::vector<ObstacleSet> obstacleSets;
  // Known Menge elements that carry nothing Throng uses (the pedestrian models' parameter
  // blocks, SpatialQuery, Elevation): each name once, sorted.
  std::vector<std::string> ignoredElements;
  std::vector<std::string> warnings;
};

// ---- Behaviour (the BFSM element of *B.xml) ----

// <Goal type id capacity weight ...> of a goal set.
struct Goal {
  enum class Kind { Point, Circle, AABB, OBB };
  Kind kind = Kind::Point;
  int id = 0;
  float capacity = 0.0f;  // 0: unlimited (attribute absent)
  float weight = 1.0f;
  glm::vec2 position{0.0f};        // point: x y; circle: centre x y; OBB: pivot corner x y
  float radius = 0.0f;             // circle
  glm::vec2 min{0.0f}, max{0.0f};  // AABB: min_x min_y max_x max_y
  float width = 0.0f, height = 0.0f, angle = 0.0f;  // OBB: size and rotation in degrees
  int line = 0;
};

struct GoalSet {
  int id = 0;
  std::vector<Goal> goals;
  int line = 0;
};

// <GoalSelector type ...>: how an agent entering the state picks its goal.
struct GoalSelector {
  enum class Kind {
    None,            // no GoalSelector element
    Identity,        // the agent's own position
    Explicit,        // goal_set + goal
    Mirror,          // the position mirrored in x and/or y (mirror_x, mirror_y)
    Random,          // uniformly from goal_set
    Weighted,        // from goal_set by goal weight
    Nearest,         // nearest goal of goal_set (straight line)
    Farthest,        // farthest goal of goal_set
    NearestNavMesh,  // nearest along the nav mesh (file_name)
    FarthestNavMesh,
    Unsupported,  // another type (warned)
  };
  Kind kind = Kind::None;
  std::string type;  // as written
  int goalSet = -1;  // goal_set; -1 when absent
  int goal = -1;     // goal (Explicit)
  bool mirrorX = false, mirrorY = false;
  bool perAgent = false;          // per_agent (Random, Weighted)
  std::filesystem::path navMesh;  // file_name (the nav-mesh kinds), resolved
  int line = 0;
};

// <VelComponent type ...>: how the preferred velocity is computed in the state.
struct VelocityComponent {
  enum class Kind { None, Goal, Zero, RoadMap, NavMesh, Unsupported };
  Kind kind = Kind::None;
  std::string type;
  std::filesystem::path file;     // road_map / nav_mesh: file_name, resolved
  float headingThreshold = 0.0f;  // nav_mesh heading_threshold, degrees (0: absent)
  int line = 0;
};

struct State {
  std::string name;
  bool final = false;
  GoalSelector goalSelector;
  VelocityComponent velocity;
  int line = 0;
};

// <Condition type ...> of a transition.
struct Condition {
  enum class Kind { GoalReached, Timer, Auto, Unsupported };
  Kind kind = Kind::Auto;
  std::string type;
  float distance = 0.0f;  // goal_reached: distance
  Distribution duration;  // timer: dist c/u/n (seconds)
  bool perAgent = false;  // timer: per_agent
  int line = 0;
};

// <Transition from to> or <Transition from> with <Target type="prob"> of weighted states.
struct TransitionTarget {
  std::string state;
  int stateIndex = -1;  // into Behavior::states
  float weight = 1.0f;
};
struct Transition {
  std::string from;
  int fromIndex = -1;
  std::vector<TransitionTarget> targets;  // one for `to`, several for a probabilistic target
  Condition condition;
  int line = 0;
};

struct Behavior {
  std::filesystem::path source;
  std::vector<GoalSet> goalSets;
  std::vector<State> states;
  std::vector<Transition> transitions;
  std::vector<std::string> warnings;
  const GoalSet* findGoalSet(int id) const;
  int findState(std::string_view name) const;  // index or -1
};

// ---- Navigation mesh (.nav, Menge's text format) ----
// vertex count, "x y" each; edge count, "v0 v1 node0 node1" each (a portal between two nodes);
// obstacle count, "v0 v1 node next" each (next: following obstacle of the outline, -1 none);
// then node groups: a name, a node count, and per node "cx cy", "n v0 .. vn-1" (its polygon),
// "a b c" (height plane z = a·x + b·y + c), "m e0 .. em-1" (its edges), "k o0 .. ok-1".
struct NavMesh {
  struct Edge {
    uint32_t v0 = 0, v1 = 0;
    uint32_t node0 = 0, node1 = 0;
  };
  struct Obstacle {
    uint32_t v0 = 0, v1 = 0;
    uint32_t node = 0;
    int32_t next = -1;
  };
  struct Node {
    glm::vec2 center{0.0f};
    std::vector<uint32_t> polygon;  // vertex indices
    glm::vec3 plane{0.0f};          // a, b, c
    std::vector<uint32_t> edges;    // into edges
    std::vector<uint32_t> obstacles;
    std::vector<uint32_t> neighbors;  // nodes across this node's edges (adjacency)
    uint32_t group = 0;               // into groups
  };
  struct Group {
    std::string name;
    uint32_t firstNode = 0;
    uint32_t nodeCount = 0;
  };
  std::filesystem::path source;
  std::vector<glm::vec2> vertices;
  std::vector<Edge> edges;
  std::vector<Obstacle> obstacles;
  std::vector<Node> nodes;
  std::vector<Group> groups;
};

// ---- Road map (velocity component road_map: a graph of way points) ----
// vertex count, "degree x y" each; edge count, "from to" each (undirected); each vertex's
// degree must equal the number of edges that name it.
struct RoadMap {
  std::filesystem::path source;
  std::vector<glm::vec2> vertices;
  std::vector<std::pair<uint32_t, uint32_t>> edges;
};

// ---- Project ----

struct MengeScenario {
  std::filesystem::path project;
  std::string model;  // Project's model attribute ("orca", ...), informative
  Scene scene;
  Behavior behavior;
  std::vector<NavMesh> navMeshes;     // every distinct .nav the scene or behaviour names
  std::vector<RoadMap> roadMaps;      // every distinct road map the behaviour names
  std::vector<std::string> warnings;  // the project's own, then the scene's and behaviour's
};

// Reads a project file and what it names: scene and behaviour resolved against the project's
// folder, nav meshes and road maps against the folder of the file naming them. Also checks that
// every group's initial state exists in the behaviour.
MengeScenario readMengeProject(const std::filesystem::path& projectXml);
Scene readMengeScene(const std::filesystem::path& sceneXml);
Behavior readMengeBehavior(const std::filesystem::path& behaviorXml);
NavMesh readNavMesh(const std::filesystem::path& navFile);
RoadMap readRoadMap(const std::filesystem::path& roadMapFile);

// The same from text in memory; `source` names it in messages and is the folder base for the
// files it references.
Scene parseMengeScene(std::string_view xml, const std::filesystem::path& source);
Behavior parseMengeBehavior(std::string_view xml, const std::filesystem::path& source);
NavMesh parseNavMesh(std::string_view text, const std::filesystem::path& source);
RoadMap parseRoadMap(std::string_view text, const std::filesystem::path& source);

}  // namespace throng::menge
