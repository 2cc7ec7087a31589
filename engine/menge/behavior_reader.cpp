// The BFSM (behaviour) file: goal sets, states with their goal selector and velocity component,
// and transitions with their condition.
#include <algorithm>
#include <unordered_map>
#include <unordered_set>

#include "menge/menge.h"
#include "menge/read_file.h"
#include "menge/xml_support.h"

namespace throng::menge {

using detail::contains;
using detail::elements;
using detail::XmlDocument;

namespace {

// Goal ids and goal-set ids are written as integers; anything beyond int32 is a typo.
constexpr uint64_t kMaxId = INT32_MAX;
// Transitions times their targets (a `from` list times a probabilistic target's states).
constexpr size_t kMaxTransitionTargets = 1'000'000;

// Name and id lookups while reading, so that large files stay linear.
struct Index {
  std::unordered_map<std::string, int> states;
  std::unordered_map<int, size_t> goalSets;
  size_t transitionTargets = 0;
};

bool readGoalShape(const XmlDocument& doc, pugi::xml_node node, Goal& goal) {
  const std::string type = doc.requireString(node, "type");
  const auto check = [&](std::initializer_list<std::string_view> own) {
    for (const pugi::xml_attribute a : node.attributes()) {
      if (!contains(own, a.name()) && !contains({"type", "id", "capacity", "weight"}, a.name())) {
        doc.warn(node, "attribute '", a.name(), "' is not supported and was ignored");
      }
    }
  };
  if (type == "point") {
    goal.kind = Goal::Kind::Point;
    check({"x", "y"});
    goal.position = {doc.requireFloat(node, "x"), doc.requireFloat(node, "y")};
  } else if (type == "circle") {
    goal.kind = Goal::Kind::Circle;
    check({"x", "y", "radius"});
    goal.position = {doc.requireFloat(node, "x"), doc.requireFloat(node, "y")};
    goal.radius = doc.requireFloat(node, "radius");
    if (goal.radius < 0.0f) doc.fail(node, "expected radius >= 0");
  } else if (type == "AABB") {
    goal.kind = Goal::Kind::AABB;
    check({"min_x", "min_y", "max_x", "max_y"});
    goal.min = {doc.requireFloat(node, "min_x"), doc.requireFloat(node, "min_y")};
    goal.max = {doc.requireFloat(node, "max_x"), doc.requireFloat(node, "max_y")};
    if (goal.min.x > goal.max.x || goal.min.y > goal.max.y) {
      doc.fail(node, "expected min_x <= max_x and min_y <= max_y");
    }
  } else if (type == "OBB") {
    goal.kind = Goal::Kind::OBB;
    check({"x", "y", "width", "height", "angle"});
    goal.position = {doc.requireFloat(node, "x"), doc.requireFloat(node, "y")};
    goal.width = doc.requireFloat(node, "width");
    goal.height = doc.requireFloat(node, "height");
    goal.angle = doc.optionalFloat(node, "angle", 0.0f);
    if (goal.width < 0.0f || goal.height < 0.0f) doc.fail(node, "expected width, height >= 0");
  } else {
    doc.warn(node, "goal type not supported; the goal was ignored");
    return false;
  }
  return true;
}

void readGoalSet(const XmlDocument& doc, pugi::xml_node node, Behavior& behavior, Index& index) {
  doc.checkAttributes(node, {"id"});
  GoalSet set;
  set.id = static_cast<int>(doc.requireCount(node, "id", kMaxId));
  set.line = doc.line(node);
  if (!index.goalSets.emplace(set.id, behavior.goalSets.size()).second) {
    doc.fail(node, "goal set id ", set.id, " defined twice");
  }
  std::unordered_set<int> goalIds;
  for (const pugi::xml_node child : elements(node)) {
    if (std::string_view(child.name()) != "Goal") {
      doc.warn(child, "element not supported in <GoalSet> and was ignored");
      continue;
    }
    Goal goal;
    goal.id = static_cast<int>(doc.requireCount(child, "id", kMaxId));
    goal.line = doc.line(child);
    goal.capacity = doc.optionalFloat(child, "capacity", 0.0f);
    goal.weight = doc.optionalFloat(child, "weight", 1.0f);
    if (goal.capacity < 0.0f || goal.weight < 0.0f)
      doc.fail(child, "expected capacity, weight >= 0");
    if (!goalIds.insert(goal.id).second) {
      doc.fail(child, "goal id ", goal.id, " defined twice in goal set ", set.id);
    }
    if (readGoalShape(doc, child, goal)) set.goals.push_back(goal);
  }
  behavior.goalSets.push_back(std::move(set));
}

GoalSelector readGoalSelector(const XmlDocument& doc, pugi::xml_node node) {
  GoalSelector s;
  s.type = doc.requireString(node, "type");
  s.line = doc.line(node);
  using K = GoalSelector::Kind;
  const auto goalSet = [&] {
    s.goalSet = static_cast<int>(doc.requireCount(node, "goal_set", kMaxId));
  };
  if (s.type == "identity") {
    s.kind = K::Identity;
    doc.checkAttributes(node, {"type"});
  } else if (s.type == "explicit") {
    s.kind = K::Explicit;
    doc.checkAttributes(node, {"type", "goal_set", "goal"});
    goalSet();
    s.goal = static_cast<int>(doc.requireCount(node, "goal", kMaxId));
  } else if (s.type == "mirror") {
    s.kind = K::Mirror;
    doc.checkAttributes(node, {"type", "mirror_x", "mirror_y"});
    s.mirrorX = doc.optionalBool(node, "mirror_x", false);
    s.mirrorY = doc.optionalBool(node, "mirror_y", false);
  } else if (s.type == "random" || s.type == "weighted") {
    s.kind = s.type == "random" ? K::Random : K::Weighted;
    doc.checkAttributes(node, {"type", "goal_set", "per_agent"});
    goalSet();
    s.perAgent = doc.optionalBool(node, "per_agent", false);
  } else if (s.type == "nearest" || s.type == "farthest") {
    s.kind = s.type == "nearest" ? K::Nearest : K::Farthest;
    doc.checkAttributes(node, {"type", "goal_set"});
    goalSet();
  } else if (s.type == "nearest_nav_mesh" || s.type == "farthest_nav_mesh") {
    s.kind = s.type == "nearest_nav_mesh" ? K::NearestNavMesh : K::FarthestNavMesh;
    doc.checkAttributes(node, {"type", "goal_set", "file_name"});
    goalSet();
    s.navMesh = doc.resolve(doc.requireString(node, "file_name"));
  } else {
    s.kind = K::Unsupported;
    doc.warn(node, "goal selector type not supported; the state keeps no goal selector");
  }
  return s;
}

VelocityComponent readVelocity(const XmlDocument& doc, pugi::xml_node node) {
  VelocityComponent v;
  v.type = doc.requireString(node, "type");
  v.line = doc.line(node);
  using K = VelocityComponent::Kind;
  if (v.type == "goal" || v.type == "zero") {
    v.kind = v.type == "goal" ? K::Goal : K::Zero;
    doc.checkAttributes(node, {"type"});
  } else if (v.type == "road_map") {
    v.kind = K::RoadMap;
    doc.checkAttributes(node, {"type", "file_name"});
    v.file = doc.resolve(doc.requireString(node, "file_name"));
  } else if (v.type == "nav_mesh") {
    v.kind = K::NavMesh;
    doc.checkAttributes(node, {"type", "file_name", "heading_threshold"});
    v.file = doc.resolve(doc.requireString(node, "file_name"));
    v.headingThreshold = doc.optionalFloat(node, "heading_threshold", 0.0f);
  } else {
    v.kind = K::Unsupported;
    doc.warn(node, "velocity component type not supported");
  }
  return v;
}

void readState(const XmlDocument& doc, pugi::xml_node node, Behavior& behavior, Index& index) {
  doc.checkAttributes(node, {"name", "final"});
  State state;
  state.name = doc.requireString(node, "name");
  state.final = doc.optionalBool(node, "final", false);
  state.line = doc.line(node);
  if (!index.states.emplace(state.name, static_cast<int>(behavior.states.size())).second) {
    doc.fail(node, "state '", state.name, "' defined twice");
  }
  for (const pugi::xml_node child : elements(node)) {
    const std::string name = child.name();
    if (name == "GoalSelector" && state.goalSelector.kind == GoalSelector::Kind::None) {
      state.goalSelector = readGoalSelector(doc, child);
    } else if (name == "VelComponent" && state.velocity.kind == VelocityComponent::Kind::None) {
      state.velocity = readVelocity(doc, child);
    } else if (name == "GoalSelector" || name == "VelComponent") {
      doc.warn(child, "a state's second <", name, "> was ignored");
    } else {
      doc.warn(child, "element not supported in <State> and was ignored");
    }
  }
  behavior.states.push_back(std::move(state));
}

Condition readCondition(const XmlDocument& doc, pugi::xml_node node) {
  Condition c;
  c.type = doc.requireString(node, "type");
  c.line = doc.line(node);
  if (c.type == "goal_reached") {
    c.kind = Condition::Kind::GoalReached;
    doc.checkAttributes(node, {"type", "distance"});
    c.distance = doc.optionalFloat(node, "distance", 0.0f);
    if (c.distance < 0.0f) doc.fail(node, "expected distance >= 0");
  } else if (c.type == "timer") {
    c.kind = Condition::Kind::Timer;
    doc.checkAttributes(
        node, {"type", "dist", "value", "min", "max", "mean", "stddev", "seed", "per_agent"});
    c.duration = doc.readDistribution(node, "");
    c.perAgent = doc.optionalBool(node, "per_agent", false);
  } else if (c.type == "auto") {
    c.kind = Condition::Kind::Auto;
    doc.checkAttributes(node, {"type"});
  } else {
    c.kind = Condition::Kind::Unsupported;
    doc.warn(node, "condition type not supported; the transition never fires");
  }
  return c;
}

std::vector<TransitionTarget> readTarget(const XmlDocument& doc, pugi::xml_node node) {
  const std::string type = doc.requireString(node, "type");
  if (type != "prob") doc.fail(node, "expected a target of type prob");
  doc.checkAttributes(node, {"type"});
  std::vector<TransitionTarget> targets;
  for (const pugi::xml_node child : elements(node)) {
    if (std::string_view(child.name()) != "State") {
      doc.warn(child, "element not supported in <Target> and was ignored");
      continue;
    }
    doc.checkAttributes(child, {"name", "weight"});
    const float weight = doc.optionalFloat(child, "weight", 1.0f);
    if (weight < 0.0f) doc.fail(child, "expected weight >= 0");
    targets.push_back({doc.requireString(child, "name"), -1, weight});
  }
  if (targets.empty()) doc.fail(node, "expected at least one <State name weight>");
  return targets;
}

// Menge's `from` may list several states separated by commas: one transition each.
std::vector<std::string> splitNames(const std::string& list) {
  std::vector<std::string> names;
  size_t start = 0;
  while (start <= list.size()) {
    const size_t end = std::min(list.find(',', start), list.size());
    std::string name = list.substr(start, end - start);
    name.erase(0, name.find_first_not_of(" \t"));
    name.erase(name.find_last_not_of(" \t") + 1);
    names.push_back(name);
    start = end + 1;
  }
  return names;
}

void readTransition(const XmlDocument& doc, pugi::xml_node node, Behavior& behavior, Index& index) {
  doc.checkAttributes(node, {"from", "to"});
  Transition t;
  t.line = doc.line(node);
  const std::string from = doc.requireString(node, "from");
  if (const pugi::xml_attribute to = node.attribute("to"))
    t.targets.push_back({to.value(), -1, 1.0f});
  bool haveCondition = false;
  for (const pugi::xml_node child : elements(node)) {
    const std::string name = child.name();
    if (name == "Condition" && !haveCondition) {
      t.condition = readCondition(doc, child);
      haveCondition = true;
    } else if (name == "Target" && t.targets.empty()) {
      t.targets = readTarget(doc, child);
    } else {
      doc.warn(child, "element not supported (or repeated) in <Transition> and was ignored");
    }
  }
  if (!haveCondition) doc.fail(node, "expected a <Condition>");
  if (t.targets.empty()) doc.fail(node, "expected a 'to' attribute or a <Target>");
  const std::vector<std::string> fromNames = splitNames(from);
  index.transitionTargets += fromNames.size() * t.targets.size();
  if (index.transitionTargets > kMaxTransitionTargets) {
    doc.fail(node, "expected at most ", kMaxTransitionTargets,
             " transition targets in all (from-states times target states)");
  }
  for (const std::string& name : fromNames) {
    t.from = name;
    behavior.transitions.push_back(t);
  }
}

int stateIndex(const XmlDocument& doc, const Index& index, const std::string& name, int line) {
  const auto found = index.states.find(name);
  if (found == index.states.end()) {
    throng::fail(doc.source().string(), ":", line, ": <Transition>: state '", name,
                 "' is not defined");
  }
  return found->second;
}

// Names and ids refer to states and goal sets anywhere in the file: checked once all are read.
void resolveReferences(const XmlDocument& doc, const Index& index, Behavior& behavior) {
  for (Transition& t : behavior.transitions) {
    t.fromIndex = stateIndex(doc, index, t.from, t.line);
    for (TransitionTarget& target : t.targets) {
      target.stateIndex = stateIndex(doc, index, target.state, t.line);
    }
  }
  for (const State& state : behavior.states) {
    const GoalSelector& s = state.goalSelector;
    if (s.goalSet < 0) continue;
    const auto found = index.goalSets.find(s.goalSet);
    const std::string where = concat(doc.source().string(), ":", s.line, ": <GoalSelector>: ");
    if (found == index.goalSets.end()) fail(where, "goal set ", s.goalSet, " is not defined");
    const GoalSet* set = &behavior.goalSets[found->second];
    if (s.kind == GoalSelector::Kind::Explicit &&
        std::none_of(set->goals.begin(), set->goals.end(),
                     [&](const Goal& g) { return g.id == s.goal; })) {
      fail(where, "goal ", s.goal, " is not in goal set ", s.goalSet);
    }
  }
}

}  // namespace

const GoalSet* Behavior::findGoalSet(int id) const {
  const auto found =
      std::find_if(goalSets.begin(), goalSets.end(), [&](const GoalSet& s) { return s.id == id; });
  return found == goalSets.end() ? nullptr : &*found;
}

int Behavior::findState(std::string_view name) const {
  const auto found =
      std::find_if(states.begin(), states.end(), [&](const State& s) { return s.name == name; });
  return found == states.end() ? -1 : static_cast<int>(found - states.begin());
}

Behavior parseMengeBehavior(std::string_view xml, const std::filesystem::path& source) {
  Behavior behavior;
  behavior.source = source;
  const XmlDocument doc(xml, source, behavior.warnings);
  const pugi::xml_node root = doc.root("BFSM");
  doc.checkAttributes(root, {});
  Index index;
  for (const pugi::xml_node child : elements(root)) {
    const std::string name = child.name();
    if (name == "GoalSet") {
      readGoalSet(doc, child, behavior, index);
    } else if (name == "State") {
      readState(doc, child, behavior, index);
    } else if (name == "Transition") {
      readTransition(doc, child, behavior, index);
    } else {
      doc.warn(child, "element not supported in <BFSM> and was ignored");
    }
  }
  resolveReferences(doc, index, behavior);
  return behavior;
}

Behavior readMengeBehavior(const std::filesystem::path& behaviorXml) {
  return parseMengeBehavior(detail::readBoundedFile(behaviorXml), behaviorXml);
}

}  // namespace throng::menge
