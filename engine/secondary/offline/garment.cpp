#include "secondary/offline/garment.h"

#include "anim/default_clips.h"
#include "core/error.h"
#include "core/rng.h"
#include "secondary/offline/body_capsules.h"
#include "secondary/offline/cloth_mesh.h"
#include "secondary/offline/cloth_sim.h"
#include "secondary/offline/primary_graph.h"
#include "secondary/offline/toy_garment.h"

namespace throng::secondary {
namespace {
using nlohmann::json;

template <typename T>
T field(const json& j, const char* key, const char* where) {
  try {
    return j.at(key).get<T>();
  } catch (const json::exception&) {
    fail("garment config: ", where, ".", key, " missing or of the wrong type");
  }
}

void requireRange(double value, double lo, double hi, const char* name) {
  if (!(value >= lo && value <= hi))
    fail("garment config: ", name, " = ", value, ", expected ", lo, " to ", hi);
}

ToyGarmentOptions toyOptions(const json& c) {
  const json& t = c.at("toy");
  ToyGarmentOptions o;
  o.links = field<uint32_t>(t, "links", "toy");
  o.linkLength = field<float>(t, "link_length", "toy");
  o.substeps = field<uint32_t>(t, "substeps", "toy");
  o.drag = field<float>(t, "drag", "toy");
  requireRange(o.links, 1, 1000, "toy.links");
  requireRange(o.linkLength, 1e-3, 10, "toy.link_length");
  requireRange(o.substeps, 1, 1000, "toy.substeps");
  requireRange(o.drag, 0, 100, "toy.drag");
  return o;
}

ClothSimOptions capeSimOptions(const json& c) {
  const json& k = c.at("cape");
  ClothSimOptions o;
  o.substeps = field<uint32_t>(k, "substeps", "cape");
  o.iterations = field<uint32_t>(k, "iterations", "cape");
  o.internalDamping = field<float>(k, "internal_damping", "cape");
  requireRange(o.internalDamping, 0, 10000, "cape.internal_damping");
  validateClothSimOptions(o);
  return o;
}

CapeOptions capeMeshOptions(const json& c) {
  const json& k = c.at("cape");
  CapeOptions o;
  o.columns = field<uint32_t>(k, "columns", "cape");
  o.rows = field<uint32_t>(k, "rows", "cape");
  o.node = field<uint32_t>(c, "initial_node", "garment");
  return o;
}

Garment finish(const json& config, std::shared_ptr<const PrimaryGraph> primary,
               std::shared_ptr<const ClothMesh> mesh) {
  Garment g;
  g.config = config;
  g.primary = std::move(primary);
  g.mesh = std::move(mesh);
  const std::string name = config.at("name");
  std::vector<uint32_t> chest;
  if (name == "toy") {
    g.step = makeToyStepFunction(g.primary, g.mesh, toyOptions(config));
    chest = {1};
  } else {
    g.step = makeClothStepFunction(g.primary, g.mesh, capeSimOptions(config));
    chest = neckShoulderJoints(*g.primary);
  }
  if (initialNode(g) >= g.primary->nodes.size())
    fail("garment config: initial_node ", initialNode(g), " out of range (",
         g.primary->nodes.size(), " primary nodes)");
  const float weight = config.at("shoulder_weight");
  if (weight > 0.0f) g.term = shoulderSideTerm(g.primary, chest, weight);
  return g;
}
}  // namespace

json defaultGarmentConfig(const std::string& name) {
  json c = {{"name", name},
            {"seed", 1},
            {"initial_node", 0},
            {"velocity_jitter", 0.01},
            {"shoulder_weight", 0.05}};
  if (name == "toy") {
    c["toy"] = {{"links", 6}, {"link_length", 0.08}, {"substeps", 4}, {"drag", 10.0}};
  } else if (name == "cape") {
    c["slow"] = "";
    c["fast"] = "";
    c["cape"] = {
        {"columns", 32},   {"rows", 48},          {"bucket_width", 0.05},     {"substeps", 10},
        {"iterations", 1}, {"settle_frames", 60}, {"internal_damping", 150.0}};
  } else {
    fail("garment '", name, "': expected cape or toy");
  }
  return c;
}

json completeGarmentConfig(const json& config) {
  if (!config.is_object() || !config.contains("name") || !config["name"].is_string())
    fail("garment config: expected an object with a \"name\"");
  json c = defaultGarmentConfig(config["name"]);
  for (auto it = config.begin(); it != config.end(); ++it) {
    if (!c.contains(it.key())) fail("garment config: unknown field '", it.key(), "'");
    if (it->is_object()) {
      for (auto jt = it->begin(); jt != it->end(); ++jt) {
        if (!c[it.key()].contains(jt.key()))
          fail("garment config: unknown field '", it.key(), ".", jt.key(), "'");
        c[it.key()][jt.key()] = *jt;
      }
    } else {
      c[it.key()] = *it;
    }
  }
  requireRange(field<double>(c, "velocity_jitter", "garment"), 0, 10, "velocity_jitter");
  requireRange(field<double>(c, "shoulder_weight", "garment"), 0, 100, "shoulder_weight");
  field<uint64_t>(c, "seed", "garment");
  field<uint32_t>(c, "initial_node", "garment");
  if (c.contains("slow") && field<std::string>(c, "slow", "garment").empty() !=
                                field<std::string>(c, "fast", "garment").empty())
    fail("garment config: slow and fast clips must be given together");
  return c;
}

namespace {
Garment buildGarmentFrom(const json& config) {
  const json c = completeGarmentConfig(config);
  if (c["name"] == "toy") {
    auto primary = std::make_shared<const PrimaryGraph>(makeToyPrimaryGraph());
    auto mesh = std::make_shared<const ClothMesh>(makeToyChain(*primary, toyOptions(c)));
    Garment garment = finish(c, primary, mesh);
    garment.clips = skeletonIdentity("toy run graph", primary->jointNames, primary->parents);
    return garment;
  }
  const float bucketWidth = field<float>(c["cape"], "bucket_width", "cape");
  requireRange(bucketWidth, 1e-3, 1, "cape.bucket_width");
  // The pair the crowd plays: the same preparation as the renderer's --slow/--fast.
  const std::string slow = c["slow"], fast = c["fast"];
  const anim::ClipPair clips =
      slow.empty() ? anim::defaultRunPair() : anim::loadClipPair(slow, fast);
  auto primary = std::make_shared<const PrimaryGraph>(buildRunGraph(clips, bucketWidth));
  if (field<uint32_t>(c, "initial_node", "garment") >= primary->nodes.size())
    fail("garment config: initial_node out of range (", primary->nodes.size(), " primary nodes)");
  auto mesh = std::make_shared<const ClothMesh>(makeCape(*primary, capeMeshOptions(c)));
  Garment garment = finish(c, primary, mesh);
  garment.clips = clipPairIdentity(clips);
  return garment;
}

Garment restoreGarmentFrom(const json& config, PrimaryGraph primary, ClothMesh mesh) {
  json stored = config;
  // Graphs explored before the cape had internal damping resume without it.
  if (stored.is_object() && stored.contains("cape") && stored["cape"].is_object() &&
      !stored["cape"].contains("internal_damping"))
    stored["cape"]["internal_damping"] = 0.0;
  return finish(completeGarmentConfig(stored),
                std::make_shared<const PrimaryGraph>(std::move(primary)),
                std::make_shared<const ClothMesh>(std::move(mesh)));
}

}  // namespace

// The configuration is user JSON (--garment-config, a .tsg's CONF chunk): a value of the wrong
// type anywhere is an Error naming the garment configuration, never a JSON library exception.
Garment buildGarment(const json& config) {
  try {
    return buildGarmentFrom(config);
  } catch (const json::exception& e) {
    fail("garment config: ", e.what());
  }
}

Garment restoreGarment(const json& config, PrimaryGraph primary, ClothMesh mesh) {
  try {
    return restoreGarmentFrom(config, std::move(primary), std::move(mesh));
  } catch (const json::exception& e) {
    fail("garment config: ", e.what());
  }
}

uint32_t initialNode(const Garment& garment) {
  return garment.config.at("initial_node").get<uint32_t>();
}

ClothState initialClothState(const Garment& garment) {
  const uint32_t node = initialNode(garment);
  ClothState s;
  if (garment.config["name"] == "toy") {
    s = toyRestState(*garment.mesh, *garment.primary, node);
  } else {
    const uint32_t frames = garment.config["cape"].at("settle_frames");
    s = settleCloth(garment.step, *garment.primary,
                    restState(*garment.mesh, *garment.primary, node), node, frames);
  }
  const float jitter = garment.config.at("velocity_jitter");
  Rng rng(garment.config.at("seed").get<uint64_t>(), 7);
  for (glm::vec3& v : s.velocities)
    for (int a = 0; a < 3; ++a) v[a] += rng.uniform(-jitter, jitter);
  return s;
}

GarmentTerm shoulderSideTerm(std::shared_ptr<const PrimaryGraph> primary,
                             std::vector<uint32_t> joints, float weight) {
  if (joints.empty()) fail("shoulder term: the skeleton has no neck or shoulder joint");
  std::vector<float> planeZ;  // the chest plane faces +z in character space
  for (uint32_t n = 0; n < primary->nodes.size(); ++n) {
    float z = 0.0f;
    for (uint32_t j : joints) z += primary->pose(n)[j].position.z;
    planeZ.push_back(z / float(joints.size()));
  }
  return [planeZ = std::move(planeZ), weight](FrameView a, FrameView b, uint32_t node) {
    const float z = planeZ.at(node);
    int64_t difference = 0;
    for (const glm::vec3& p : a.positions) difference += p.z > z;
    for (const glm::vec3& p : b.positions) difference -= p.z > z;
    return weight * float(std::llabs(difference)) / float(std::max<size_t>(1, a.positions.size()));
  };
}

}  // namespace throng::secondary
