// The project file: which scene and behaviour, then the nav meshes and road maps they name.
#include <algorithm>
#include <unordered_set>

#include "menge/menge.h"
#include "menge/read_file.h"
#include "menge/xml_support.h"

namespace throng::menge {

namespace {

void addUnique(std::vector<std::filesystem::path>& paths, const std::filesystem::path& path) {
  if (!path.empty() && std::find(paths.begin(), paths.end(), path) == paths.end()) {
    paths.push_back(path);
  }
}

// Every group's initial state must be a state of the behaviour.
void checkInitialStates(const Scene& scene, const Behavior& behavior) {
  std::unordered_set<std::string> states;
  for (const State& state : behavior.states) states.insert(state.name);
  for (const AgentGroup& group : scene.groups) {
    if (!group.state.empty() && !states.contains(group.state)) {
      fail(scene.source.string(), ":", group.line, ": <AgentGroup>: initial state '", group.state,
           "' is not a state of ", behavior.source.string());
    }
  }
}

void loadResources(MengeScenario& scenario) {
  std::vector<std::filesystem::path> navMeshes, roadMaps;
  for (const ObstacleSet& set : scenario.scene.obstacleSets) {
    if (set.kind == ObstacleSet::Kind::NavMesh) addUnique(navMeshes, set.navMesh);
  }
  for (const State& state : scenario.behavior.states) {
    addUnique(navMeshes, state.goalSelector.navMesh);
    if (state.velocity.kind == VelocityComponent::Kind::NavMesh) {
      addUnique(navMeshes, state.velocity.file);
    } else if (state.velocity.kind == VelocityComponent::Kind::RoadMap) {
      addUnique(roadMaps, state.velocity.file);
    }
  }
  for (const auto& path : navMeshes) scenario.navMeshes.push_back(readNavMesh(path));
  for (const auto& path : roadMaps) scenario.roadMaps.push_back(readRoadMap(path));
}

}  // namespace

MengeScenario readMengeProject(const std::filesystem::path& projectXml) {
  MengeScenario scenario;
  scenario.project = projectXml;
  const std::string text = detail::readBoundedFile(projectXml);
  std::filesystem::path scenePath, behaviorPath;
  {
    const detail::XmlDocument doc(text, projectXml, scenario.warnings);
    const pugi::xml_node root = doc.root("Project");
    // view and dumpPath concern Menge's own viewer; scbVersion its trajectory output.
    doc.checkAttributes(root, {"scene", "behavior", "view", "model", "dumpPath", "scbVersion",
                               "duration", "random", "timeStep", "subSteps", "output"});
    scenePath = doc.resolve(doc.requireString(root, "scene"));
    behaviorPath = doc.resolve(doc.requireString(root, "behavior"));
    scenario.model = root.attribute("model").value();
  }
  scenario.scene = readMengeScene(scenePath);
  scenario.behavior = readMengeBehavior(behaviorPath);
  checkInitialStates(scenario.scene, scenario.behavior);
  loadResources(scenario);
  for (const auto* list : {&scenario.scene.warnings, &scenario.behavior.warnings}) {
    scenario.warnings.insert(scenario.warnings.end(), list->begin(), list->end());
  }
  return scenario;
}

}  // namespace throng::menge
