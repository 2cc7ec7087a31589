#pragma once
// Goals of a crowd and the small per-group state machines that pick them (docs/design.md, "Goals
// and navigation"). Plain data on the CPU: a goal is a region of the ground (point, circle,
// axis-aligned box, oriented box); goal sets hold goals; each group of agents runs a state
// machine whose states choose a goal from a set (explicit, random, nearest, shared) and say
// what happens on arrival (wait, then the next state; the next goal; stop).
//
// Why on the CPU: transitions are branchy, rare (a few per agent in a whole run) and every one
// needs a new path, which the CPU plans anyway (nav_mesh.h); the GPU only follows the paths each
// frame (nav_jobs.h). GoalMachine::evaluate costs O(agents) plus the plans it makes, and is run
// every N frames on read-back positions (GoalSteering::update), not every frame.
//
// Coordinates are the ground plane (x, z) as glm::vec2 (x, y = z).
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "crowd/nav_mesh.h"

namespace throng::menge {
struct Goal;
}

namespace throng::crowd {

// A goal region. An agent has reached it when its distance to the region is at most the state's
// `reach` (inside: distance 0).
struct Goal {
  enum class Shape { Point, Circle, Box, OrientedBox };
  Shape shape = Shape::Point;
  glm::vec2 center{0.0f};    // point, circle centre, box centre
  float radius = 0.0f;       // circle
  glm::vec2 halfSize{0.0f};  // box and oriented box: half width (local x), half depth (local z)
  float angle = 0.0f;        // oriented box: rotation of its local x axis from x towards z (rad)
  float weight = 1.0f;       // random selection draws goals in proportion to their weight
};

Goal pointGoal(glm::vec2 p);
Goal circleGoal(glm::vec2 center, float radius);
Goal boxGoal(glm::vec2 min, glm::vec2 max);
Goal orientedBoxGoal(glm::vec2 center, glm::vec2 halfSize, float angle);

// Distance from p to the region (0 inside).
float goalDistance(const Goal& goal, glm::vec2 p);
// The point of the region closest to p (p itself inside).
glm::vec2 closestGoalPoint(const Goal& goal, glm::vec2 p);
// A point inside the region, uniform over its area, deterministic from (agent, draw, seed).
glm::vec2 sampleGoalPoint(const Goal& goal, uint32_t agent, uint32_t draw, uint32_t seed);
// Problems with the goal (negative sizes, non-finite values); empty when valid.
std::vector<std::string> validateGoal(const Goal& goal);

struct GoalSet {
  std::vector<Goal> goals;
};

// How an agent entering a state picks its goal of `goalSet`.
struct GoalChoice {
  enum class Kind {
    Explicit,  // goal `goal` of the set
    Random,    // drawn by weight from (agent, visit, seed)
    Nearest,   // the nearest to the agent (goalDistance)
    Shared,    // one goal for the whole group in this state, drawn by weight from (group, seed)
    Identity,  // where the agent stands (no set)
    Mirror,    // where the agent stands mirrored through the origin's axes (no set; Menge's
               // mirror selector: mirrorX negates x, mirrorZ negates z)
  };
  Kind kind = Kind::Explicit;
  uint32_t goalSet = 0;
  uint32_t goal = 0;          // Explicit
  bool sampleInside = false;  // target a point sampled inside the region, else its closest point
  bool mirrorX = false, mirrorZ = false;  // Mirror
  // Identity and Mirror target a point of the agent's own, not a goal of a set.
  bool ownPoint() const { return kind == Kind::Identity || kind == Kind::Mirror; }
};

inline constexpr uint32_t kNoState = std::numeric_limits<uint32_t>::max();
inline constexpr float kNever = std::numeric_limits<float>::infinity();

// One state of a group's machine. Transitions: on arrival (distance ≤ reach) the action; a timer
// (`leaveAfter` seconds in the state, reached or not) goes to `next` as well.
struct GoalState {
  enum class Arrival {
    Wait,      // wait `waitSeconds`, then enter `next` (kNoState: stay, as Stop)
    NextGoal,  // choose another goal of the set (explicit and shared: the next one; random: a new
               // draw other than the current; nearest: the nearest other than the current)
    Stop,      // final: the agent stays at its target
  };
  GoalChoice choice;
  Arrival onArrival = Arrival::Stop;
  float waitSeconds = 0.0f;
  uint32_t next = kNoState;
  float reach = 0.25f;        // goal reached within this distance (m)
  float leaveAfter = kNever;  // timer transition to `next` (s)
};

// A group's machine; its agents start in `initial`.
struct GoalBehavior {
  std::vector<GoalState> states;
  uint32_t initial = 0;
  float maxSpeed = 1.3f;  // m/s, written into the steering goal
};

// Everything GoalSteering is built from.
struct GoalScene {
  std::vector<GoalSet> goalSets;
  std::vector<GoalBehavior> groups;
  std::vector<uint32_t> agentGroup;  // per agent: its group, or kNoState for no goals (inactive)
  NavMesh navMesh;                   // empty: none
  RoadMap roadMap;                   // used when there is no nav mesh; empty: none
  float waypointReach = 0.5f;        // a waypoint within this distance is passed (m)
  float cornerClearance = 0.5f;      // nav-mesh corners kept this far off walls (planOnNavMesh)
  // An agent walking to a goal whose remaining path (from where it stands) has not shrunk by
  // `stuckDistance` for `stuckSeconds`, and which cannot see the waypoint it heads for (off the
  // nav mesh or behind a wall; GoalMachine::evaluate), is planned again from where it stands: the
  // crowd pushed it off its path, past a corner and back behind it, or behind a wall. Walking
  // agents shrink their path by about a metre a second and queued ones see their waypoint, so
  // plans for this are rare (none in free walking; none without a nav mesh or road map, where
  // the plan is the straight line again). 0: never.
  float stuckSeconds = 10.0f;
  float stuckDistance = 0.5f;
  // Held back like that (stuck, heading straight for its goal and seeing it) within this
  // distance (m) of an agent standing at the same goal, an agent has arrived: it joined the
  // crowd at the goal, which those standing there keep it from getting nearer. Without it the
  // last agents to a goal many share never arrive. 0: never.
  float crowdReach = 1.0f;
  uint32_t seed = 1;
};
// Problems with the scene (indices out of range, bad goals); empty when valid.
std::vector<std::string> validateGoalScene(const GoalScene& scene, size_t agents);

// A Menge goal (point, circle, AABB, OBB with its pivot corner and angle in degrees) as a Goal;
// Menge (x, y) becomes (x, z).
Goal goalFromMenge(const menge::Goal& goal);

// Where one agent is in its machine.
struct AgentGoal {
  uint32_t state = kNoState;   // kNoState: no goals
  uint32_t goal = 0;           // index in the state's set
  glm::vec2 target{0.0f};      // the point it walks to
  double enteredAt = 0.0;      // seconds
  double reachedAt = -1.0;     // < 0: not reached yet in this state
  float bestRemaining = 0.0f;  // the shortest remaining path length seen since it was planned
  double progressAt = 0.0;     // when that was last shortened by the scene's stuckDistance
  // The goal of a set it last reached (its set kNoState: none since it chose one), kept through
  // the states after it: agents standing there are the crowd at that goal.
  uint32_t arrivedSet = kNoState;
  uint32_t arrivedGoal = 0;
  uint32_t visits = 0;  // goals chosen so far (hashed into random draws)
  bool done = false;    // in a final state, reached
};

// The CPU side: every agent's machine and planned path. `evaluate` runs the machines on the
// current positions and plans a path (planPath) for every agent whose target changed.
class GoalMachine {
 public:
  // Throws Error when the scene is invalid. Nothing is chosen until the first evaluate.
  GoalMachine(GoalScene scene, size_t agents);

  // Runs every machine at time `seconds` with the agents' positions (x, z); returns the agents
  // whose path changed (their paths() entry is new). `waypoints`: per agent the index in its path
  // of the waypoint it heads for (NavBuffers::progress), for the stuck rule (GoalScene::
  // stuckSeconds); empty: a stuck agent is planned again whether it sees its waypoint or not.
  std::vector<uint32_t> evaluate(std::span<const glm::vec2> positions, double seconds,
                                 std::span<const uint32_t> waypoints = {});

  const std::vector<AgentGoal>& agents() const { return agents_; }
  // Per agent: the path it follows, its start (where it was planned from) first, target last;
  // empty for agents without goals.
  const std::vector<std::vector<glm::vec2>>& paths() const { return paths_; }
  const GoalScene& scene() const { return scene_; }
  uint32_t agentsAtGoal() const;  // agents done (in a final state, reached)
  bool allDone() const;           // every agent with goals is done
  uint64_t plans() const { return plans_; }
  uint64_t partialPlans() const { return partialPlans_; }    // plans that fell back (nav_mesh.h)
  uint64_t stuckPlans() const { return stuckPlans_; }        // of plans(): agents that were stuck
  uint64_t crowdArrivals() const { return crowdArrivals_; }  // arrivals in the crowd at a goal

 private:
  void enter(uint32_t agent, uint32_t state, glm::vec2 p, double seconds);
  void choose(uint32_t agent, glm::vec2 p, bool another);
  bool step(uint32_t agent, glm::vec2 p, double seconds, bool joinedCrowd);
  bool joinsCrowdAtGoal(uint32_t agent, std::span<const glm::vec2> positions, double seconds,
                        const uint32_t* waypoint) const;
  bool replanIfStuck(uint32_t agent, glm::vec2 p, double seconds, const uint32_t* waypoint);
  bool seesWaypoint(uint32_t agent, glm::vec2 p, uint32_t waypoint) const;
  void plan(uint32_t agent, glm::vec2 p, double seconds);

  GoalScene scene_;
  std::vector<AgentGoal> agents_;
  std::vector<std::vector<glm::vec2>> paths_;
  std::vector<std::vector<uint32_t>> shared_;  // per group, per state: the shared goal or kNoState
  uint64_t plans_ = 0;
  uint64_t partialPlans_ = 0;
  uint64_t stuckPlans_ = 0;
  uint64_t crowdArrivals_ = 0;
  bool started_ = false;
};

}  // namespace throng::crowd
