// The Experiment (scene) file: agent profiles, agent groups expanded into start positions, and
// obstacle sets.
#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/file_io.h"
#include "core/math.h"
#include "menge/menge.h"
#include "menge/read_file.h"
#include "menge/xml_support.h"

namespace throng::menge {

using detail::contains;
using detail::elements;
using detail::XmlDocument;

namespace {

// Elements Menge reads that describe its pedestrian models or spatial queries: nothing Throng
// uses, so they are recorded in Scene::ignoredElements rather than warned about.
constexpr std::string_view kModelElements[] = {
    "OpenSteer", "GCF", "Helbing", "Johansson", "Karamouzas", "Zanlungo", "Dummy", "ORCA", "PedVO"};
constexpr std::string_view kIgnoredSceneElements[] = {"SpatialQuery", "Elevation"};

void noteIgnored(Scene& scene, const std::string& name) {
  const auto at =
      std::lower_bound(scene.ignoredElements.begin(), scene.ignoredElements.end(), name);
  if (at == scene.ignoredElements.end() || *at != name) scene.ignoredElements.insert(at, name);
}

float* floatField(AgentProfile& profile, std::string_view name) {
  if (name == "r") return &profile.radius;
  if (name == "pref_speed") return &profile.prefSpeed;
  if (name == "max_speed") return &profile.maxSpeed;
  if (name == "max_accel") return &profile.maxAccel;
  if (name == "max_angle_vel") return &profile.maxAngleVel;
  if (name == "neighbor_dist") return &profile.neighborDist;
  if (name == "priority") return &profile.priority;
  return nullptr;
}

void readProperty(const XmlDocument& doc, pugi::xml_node node, AgentProfile& profile) {
  doc.checkAttributes(node, {"name", "dist", "value", "min", "max", "mean", "stddev", "seed"});
  const std::string name = doc.requireString(node, "name");
  float* field = floatField(profile, name);
  if (!field) {
    doc.warn(node, "property '", name, "' has no distribution support and was ignored");
    return;
  }
  const Distribution distribution = doc.readDistribution(node, "");
  if (distribution.kind == Distribution::Kind::Constant) {
    *field = distribution.value;
    return;
  }
  std::erase_if(profile.distributions, [&](const auto& d) { return d.name == name; });
  profile.distributions.push_back({name, distribution});
}

void readCommon(const XmlDocument& doc, pugi::xml_node node, AgentProfile& profile) {
  doc.checkAttributes(node, {"r", "pref_speed", "max_speed", "max_accel", "max_angle_vel",
                             "neighbor_dist", "max_neighbors", "obstacleSet", "class", "priority"});
  for (const pugi::xml_attribute attribute : node.attributes()) {
    if (float* field = floatField(profile, attribute.name())) {
      *field = doc.requireFloat(node, attribute.name());
      // A plain value replaces an inherited distribution of the same property.
      std::erase_if(profile.distributions,
                    [&](const auto& d) { return d.name == attribute.name(); });
    }
  }
  profile.maxNeighbors = static_cast<uint32_t>(
      doc.optionalCount(node, "max_neighbors", profile.maxNeighbors, UINT32_MAX));
  profile.obstacleSet = static_cast<uint32_t>(
      doc.optionalCount(node, "obstacleSet", profile.obstacleSet, UINT32_MAX));
  profile.agentClass =
      static_cast<uint32_t>(doc.optionalCount(node, "class", profile.agentClass, UINT32_MAX));
  if (profile.radius < 0.0f) doc.fail(node, "expected r >= 0");
  for (const pugi::xml_node child : elements(node)) {
    if (std::string_view(child.name()) == "Property") {
      readProperty(doc, child, profile);
    } else {
      doc.warn(child, "element not supported in <Common> and was ignored");
    }
  }
}

using ProfileIndex = std::unordered_map<std::string, size_t>;

void readProfile(const XmlDocument& doc, pugi::xml_node node, Scene& scene, ProfileIndex& index) {
  doc.checkAttributes(node, {"name", "inherits"});
  const std::string name = doc.requireString(node, "name");
  if (index.contains(name)) doc.fail(node, "profile '", name, "' defined twice");
  AgentProfile profile;
  if (const pugi::xml_attribute inherits = node.attribute("inherits")) {
    const auto parent = index.find(inherits.value());
    if (parent == index.end()) {
      doc.fail(node, "inherits '", inherits.value(),
               "', which is not a profile defined before this one");
    }
    profile = scene.profiles[parent->second];
    profile.inherits = inherits.value();
  }
  profile.name = name;
  profile.line = doc.line(node);
  for (const pugi::xml_node child : elements(node)) {
    const std::string childName = child.name();
    if (childName == "Common") {
      readCommon(doc, child, profile);
    } else if (contains(kModelElements, childName)) {
      noteIgnored(scene, childName);
    } else {
      doc.warn(child, "element not supported in <AgentProfile> and was ignored");
    }
  }
  index.emplace(name, scene.profiles.size());
  scene.profiles.push_back(std::move(profile));
}

glm::vec2 rotated(glm::vec2 p, float degrees) {
  const float radians = degrees * kPi / 180.0f;
  const float c = std::cos(radians), s = std::sin(radians);
  return {c * p.x - s * p.y, s * p.x + c * p.y};
}

// Throws unless `count` more agents stay within kMaxAgents.
void checkAgentRoom(const XmlDocument& doc, pugi::xml_node node, const Scene& scene,
                    uint64_t count) {
  if (count > kMaxAgents - scene.agents.size()) {
    doc.fail(node, "expected at most ", kMaxAgents, " agents in a scene, this generator adds ",
             count, " to ", scene.agents.size());
  }
}

// Geometric growth, so that many small generators stay linear.
void growAgents(Scene& scene, uint64_t count) {
  const size_t needed = scene.agents.size() + count;
  if (needed > scene.agents.capacity()) {
    scene.agents.reserve(std::max(needed, 2 * scene.agents.capacity()));
  }
}

void expandExplicit(const XmlDocument& doc, pugi::xml_node node, Scene& scene, uint32_t group) {
  doc.checkAttributes(node, {"type"});
  for (const pugi::xml_node agent : elements(node)) {
    if (std::string_view(agent.name()) != "Agent") {
      doc.warn(agent, "element not supported in an explicit <Generator> and was ignored");
      continue;
    }
    doc.checkAttributes(agent, {"p_x", "p_y"});
    checkAgentRoom(doc, agent, scene, 1);
    scene.agents.push_back(
        {{doc.requireFloat(agent, "p_x"), doc.requireFloat(agent, "p_y")}, group});
  }
}

void expandRectGrid(const XmlDocument& doc, pugi::xml_node node, Generator& generator, Scene& scene,
                    uint32_t group) {
  generator.anchor = {doc.requireFloat(node, "anchor_x"), doc.requireFloat(node, "anchor_y")};
  generator.offset = {doc.requireFloat(node, "offset_x"), doc.requireFloat(node, "offset_y")};
  generator.countX = static_cast<uint32_t>(doc.requireCount(node, "count_x", kMaxAgents));
  generator.countY = static_cast<uint32_t>(doc.requireCount(node, "count_y", kMaxAgents));
  generator.rotation = doc.optionalFloat(node, "rotation", 0.0f);
  const uint64_t count = uint64_t{generator.countX} * generator.countY;
  checkAgentRoom(doc, node, scene, count);
  growAgents(scene, count);
  for (uint32_t v = 0; v < generator.countY; ++v) {
    for (uint32_t u = 0; u < generator.countX; ++u) {
      const glm::vec2 local(u * generator.offset.x, v * generator.offset.y);
      scene.agents.push_back({generator.anchor + rotated(local, generator.rotation), group});
    }
  }
}

// Menge's HexLatticeGenerator: disks of the radius that packs `density` agents per m², rows
// 2r apart along the row direction, rows sqrt(3)·r apart across it; whole rows (or bands of a
// long and a short row) until the population is reached, so a few more may be placed.
struct HexLayout {
  uint64_t rowPop = 0, rowCount = 0, total = 0;
  float nbrDist = 0.0f, rowDist = 0.0f, actualWidth = 0.0f;
};

HexLayout hexLayout(const XmlDocument& doc, pugi::xml_node node, const Generator& g) {
  HexLayout layout;
  const float r = 1.0f / std::sqrt(2.0f * g.density * std::sqrt(3.0f));
  layout.rowDist = r * std::sqrt(3.0f);
  layout.nbrDist = 2.0f * r;
  const double limit = 2.0 * kMaxAgents;  // beyond this the lattice is too large anyway
  const auto across = [&](float spacing) {
    const double n = std::floor(double(g.width) / spacing);
    if (!(n < limit)) doc.fail(node, "expected a lattice of at most ", kMaxAgents, " agents");
    return std::max<uint64_t>(1, static_cast<uint64_t>(n));
  };
  const uint64_t population = g.population;
  if (g.rowDirection == Generator::RowDirection::X) {
    layout.rowPop = across(layout.nbrDist);
    const uint64_t band = 2 * layout.rowPop - 1;
    layout.rowCount = (population / band + 1) * 2;
    layout.total = band * (layout.rowCount / 2);
    if (layout.total - (layout.rowPop - 1) > population) {
      layout.total -= layout.rowPop - 1;
      --layout.rowCount;
    }
    layout.actualWidth = float(layout.rowPop - 1) * layout.nbrDist;
  } else {
    layout.rowCount = across(layout.rowDist);
    layout.rowPop = population / layout.rowCount + 1;
    layout.total = layout.rowCount * layout.rowPop;
    layout.actualWidth = float(layout.rowCount - 1) * layout.rowDist;
  }
  return layout;
}

glm::vec2 hexLocal(const HexLayout& layout, const Generator& g, uint64_t i) {
  const float half = layout.nbrDist * 0.5f;
  if (g.rowDirection == Generator::RowDirection::X) {
    const uint64_t bandPop = layout.rowPop * 2 - 1;
    const uint64_t band = i / bandPop;
    i -= band * bandPop;
    if (i >= layout.rowPop) {
      i -= layout.rowPop;
      return {half + i * layout.nbrDist, band * 2.0f * layout.rowDist + layout.rowDist};
    }
    return {i * layout.nbrDist, band * 2.0f * layout.rowDist};
  }
  const uint64_t column = i / layout.rowPop;
  i -= layout.rowPop * column;
  return {column * layout.rowDist, i * layout.nbrDist + (column % 2 ? half : 0.0f)};
}

void expandHexLattice(const XmlDocument& doc, pugi::xml_node node, Generator& g, Scene& scene,
                      uint32_t group) {
  g.anchor = {doc.requireFloat(node, "anchor_x"), doc.requireFloat(node, "anchor_y")};
  const std::string alignment = doc.requireString(node, "alignment");
  if (alignment == "center")
    g.alignment = Generator::Alignment::Center;
  else if (alignment == "left")
    g.alignment = Generator::Alignment::Left;
  else if (alignment == "right")
    g.alignment = Generator::Alignment::Right;
  else
    doc.fail(node, "expected alignment center, left or right, got \"", alignment, "\"");
  const std::string direction = doc.requireString(node, "row_direction");
  if (direction == "x")
    g.rowDirection = Generator::RowDirection::X;
  else if (direction == "y")
    g.rowDirection = Generator::RowDirection::Y;
  else
    doc.fail(node, "expected row_direction x or y, got \"", direction, "\"");
  g.density = doc.requireFloat(node, "density");
  g.width = doc.requireFloat(node, "width");
  g.population = static_cast<uint32_t>(doc.requireCount(node, "population", kMaxAgents));
  g.rotation = doc.optionalFloat(node, "rotation", 0.0f);
  if (!(g.density > 1e-6f)) doc.fail(node, "expected density > 0 (agents per m²)");
  if (!(g.width >= 0.0f)) doc.fail(node, "expected width >= 0");
  const HexLayout layout = hexLayout(doc, node, g);
  checkAgentRoom(doc, node, scene, layout.total);
  growAgents(scene, layout.total);
  const glm::vec2 widthAxis = rotated({layout.actualWidth, 0.0f}, g.rotation);
  glm::vec2 origin = g.anchor;
  if (g.alignment == Generator::Alignment::Center) origin -= 0.5f * widthAxis;
  if (g.alignment == Generator::Alignment::Right) origin -= widthAxis;
  for (uint64_t i = 0; i < layout.total; ++i) {
    scene.agents.push_back({origin + rotated(hexLocal(layout, g, i), g.rotation), group});
  }
}

void readGenerator(const XmlDocument& doc, pugi::xml_node node, Scene& scene, uint32_t group) {
  const std::string type = doc.requireString(node, "type");
  Generator generator;
  generator.line = doc.line(node);
  generator.firstAgent = scene.agents.size();
  if (node.attribute("displace_dist")) {
    generator.hasDisplacement = true;
    generator.displacement = doc.readDistribution(node, "displace_");
  }
  static constexpr std::string_view kDisplace[] = {
      "displace_dist", "displace_value",  "displace_min", "displace_max",
      "displace_mean", "displace_stddev", "displace_seed"};
  const auto check = [&](std::initializer_list<std::string_view> own) {
    for (const pugi::xml_attribute a : node.attributes()) {
      if (!contains(own, a.name()) && !contains(kDisplace, a.name()) &&
          a.name() != std::string_view("type")) {
        doc.warn(node, "attribute '", a.name(), "' is not supported and was ignored");
      }
    }
  };
  if (type == "explicit") {
    generator.kind = Generator::Kind::Explicit;
    check({});
    expandExplicit(doc, node, scene, group);
  } else if (type == "rect_grid") {
    generator.kind = Generator::Kind::RectGrid;
    check({"anchor_x", "anchor_y", "offset_x", "offset_y", "count_x", "count_y", "rotation"});
    expandRectGrid(doc, node, generator, scene, group);
  } else if (type == "hex_lattice") {
    generator.kind = Generator::Kind::HexLattice;
    check({"anchor_x", "anchor_y", "alignment", "row_direction", "density", "width", "population",
           "rotation"});
    expandHexLattice(doc, node, generator, scene, group);
  } else {
    doc.warn(node, "generator type not supported; its agents were not placed");
    return;
  }
  generator.agentCount = scene.agents.size() - generator.firstAgent;
  scene.groups[group].generators.push_back(std::move(generator));
}

// <ProfileSelector>/<StateSelector type="const" name>: the name, or empty (warned) otherwise.
std::string readConstSelector(const XmlDocument& doc, pugi::xml_node node) {
  const std::string type = doc.requireString(node, "type");
  if (type != "const") {
    doc.warn(node, "selector type not supported (only const); the group has none");
    return {};
  }
  doc.checkAttributes(node, {"type", "name"});
  return doc.requireString(node, "name");
}

void readGroup(const XmlDocument& doc, pugi::xml_node node, Scene& scene) {
  doc.checkAttributes(node, {});
  const uint32_t index = static_cast<uint32_t>(scene.groups.size());
  scene.groups.push_back({});
  scene.groups.back().line = doc.line(node);
  bool haveProfile = false, haveState = false;
  for (const pugi::xml_node child : elements(node)) {
    const std::string name = child.name();
    if (name == "ProfileSelector") {
      scene.groups[index].profile = readConstSelector(doc, child);
      haveProfile = true;
    } else if (name == "StateSelector") {
      scene.groups[index].state = readConstSelector(doc, child);
      haveState = true;
    } else if (name == "Generator") {
      readGenerator(doc, child, scene, index);
    } else {
      doc.warn(child, "element not supported in <AgentGroup> and was ignored");
    }
  }
  if (!haveProfile) doc.fail(node, "expected a <ProfileSelector>");
  if (!haveState) doc.fail(node, "expected a <StateSelector>");
}

Obstacle readObstacle(const XmlDocument& doc, pugi::xml_node node) {
  doc.checkAttributes(node, {"closed"});
  Obstacle obstacle;
  obstacle.line = doc.line(node);
  obstacle.closed = doc.optionalBool(node, "closed", true);
  for (const pugi::xml_node vertex : elements(node)) {
    if (std::string_view(vertex.name()) != "Vertex") {
      doc.warn(vertex, "element not supported in <Obstacle> and was ignored");
      continue;
    }
    doc.checkAttributes(vertex, {"p_x", "p_y"});
    obstacle.vertices.emplace_back(doc.requireFloat(vertex, "p_x"),
                                   doc.requireFloat(vertex, "p_y"));
  }
  if (obstacle.vertices.size() < 2) doc.fail(node, "expected at least 2 <Vertex> elements");
  return obstacle;
}

void readObstacleSet(const XmlDocument& doc, pugi::xml_node node, Scene& scene) {
  const std::string type = doc.requireString(node, "type");
  ObstacleSet set;
  set.line = doc.line(node);
  if (type == "explicit") {
    doc.checkAttributes(node, {"type", "class"});
    set.kind = ObstacleSet::Kind::Explicit;
    for (const pugi::xml_node child : elements(node)) {
      if (std::string_view(child.name()) == "Obstacle") {
        set.obstacles.push_back(readObstacle(doc, child));
      } else {
        doc.warn(child, "element not supported in <ObstacleSet> and was ignored");
      }
    }
  } else if (type == "nav_mesh") {
    doc.checkAttributes(node, {"type", "class", "file_name"});
    set.kind = ObstacleSet::Kind::NavMesh;
    set.navMesh = doc.resolve(doc.requireString(node, "file_name"));
  } else {
    doc.warn(node, "obstacle set type not supported; its obstacles were ignored");
    return;
  }
  set.obstacleClass = static_cast<uint32_t>(doc.optionalCount(node, "class", 1, UINT32_MAX));
  scene.obstacleSets.push_back(std::move(set));
}

void resolveProfiles(const XmlDocument& doc, const ProfileIndex& index, Scene& scene) {
  for (AgentGroup& group : scene.groups) {
    if (group.profile.empty()) continue;
    const auto found = index.find(group.profile);
    if (found == index.end()) {
      throng::fail(doc.source().string(), ":", group.line, ": <AgentGroup>: profile '",
                   group.profile, "' is not defined");
    }
    group.profileIndex = static_cast<int>(found->second);
  }
}

}  // namespace

Scene parseMengeScene(std::string_view xml, const std::filesystem::path& source) {
  Scene scene;
  scene.source = source;
  const XmlDocument doc(xml, source, scene.warnings);
  const pugi::xml_node root = doc.root("Experiment");
  doc.checkAttributes(root, {"version"});
  scene.version = root.attribute("version").value();
  ProfileIndex profiles;
  for (const pugi::xml_node child : elements(root)) {
    const std::string name = child.name();
    if (name == "AgentProfile") {
      readProfile(doc, child, scene, profiles);
    } else if (name == "AgentGroup") {
      readGroup(doc, child, scene);
    } else if (name == "ObstacleSet") {
      readObstacleSet(doc, child, scene);
    } else if (name == "Common") {
      doc.checkAttributes(child, {"time_step"});
      scene.timeStep = doc.optionalFloat(child, "time_step", scene.timeStep);
      if (!(scene.timeStep > 0.0f)) doc.fail(child, "expected time_step > 0");
    } else if (contains(kModelElements, name) || contains(kIgnoredSceneElements, name)) {
      noteIgnored(scene, name);
    } else {
      doc.warn(child, "element not supported in <Experiment> and was ignored");
    }
  }
  resolveProfiles(doc, profiles, scene);
  return scene;
}

Scene readMengeScene(const std::filesystem::path& sceneXml) {
  return parseMengeScene(detail::readBoundedFile(sceneXml), sceneXml);
}

}  // namespace throng::menge
