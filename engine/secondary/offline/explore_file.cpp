#include "secondary/offline/explore_file.h"

#include <algorithm>
#include <numeric>

#include "core/error.h"
#include "secondary/offline/primary_graph.h"

namespace throng::secondary {
namespace {
constexpr std::string_view kKind = "secondary motion graph (.tsg)";

ChunkReader openTsg(const std::filesystem::path& path) {
  return ChunkReader::openFile(path, kTsgMagic, kTsgVersion, kKind);
}

// The garment's name from a file's configuration, "" when it is missing or not a string (the
// configuration is the file's own JSON: any shape must be read without throwing).
std::string garmentName(const nlohmann::json& config) {
  const auto garment = config.find("garment");
  if (garment == config.end() || !garment->is_object()) return "";
  const auto name = garment->find("name");
  return name != garment->end() && name->is_string() ? name->get<std::string>() : "";
}

// Version 1 predates the identity: the cape was always explored on the built-in run.
ClipPairIdentity readClips(const ChunkReader& r, const nlohmann::json& config,
                           const PrimaryGraph& primary) {
  if (r.version() >= 2) return readClipIdentityChunks(r);
  if (garmentName(config) == "toy")
    return skeletonIdentity("toy run graph", primary.jointNames, primary.parents);
  return builtInRunIdentity();
}

nlohmann::json readConfig(const ChunkReader& r) {
  try {
    return nlohmann::json::parse(r.string("CONF"));
  } catch (const nlohmann::json::exception& e) {
    fail(r.name(), ": run config is not valid JSON (", e.what(), ")");
  }
}

uint64_t edgeCountFor(const ChunkReader& r, const std::vector<uint32_t>& stateNode,
                      const PrimaryGraph& primary) {
  uint64_t edges = 0;
  for (size_t s = 0; s < stateNode.size(); ++s) {
    if (stateNode[s] >= primary.nodes.size())
      fail(r.name(), ": state ", s, " at primary node ", stateNode[s], " of ",
           primary.nodes.size());
    edges += primary.successors[stateNode[s]].size();
  }
  return edges;
}
}  // namespace

void addClothMeshChunks(ChunkWriter& w, const ClothMesh& mesh) {
  w.add("MRST", mesh.restPositions);
  w.add("MTRI", mesh.triangles);
  w.add("MPIN", mesh.pinnedVertices);
  w.add("MPJT", mesh.pinJoints);
  w.add("MPOF", mesh.pinOffsets);
}

ClothMesh readClothMeshChunks(const ChunkReader& r) {
  ClothMesh mesh;
  mesh.restPositions = r.vector<glm::vec3>("MRST");
  mesh.triangles = r.vector<uint32_t>("MTRI");
  mesh.pinnedVertices = r.vector<uint32_t>("MPIN");
  mesh.pinJoints = r.vector<uint32_t>("MPJT");
  mesh.pinOffsets = r.vector<glm::vec3>("MPOF");
  const uint32_t v = mesh.vertexCount();
  if (mesh.triangles.size() % 3 ||
      std::any_of(mesh.triangles.begin(), mesh.triangles.end(), [&](uint32_t i) { return i >= v; }))
    fail(r.name(), ": mesh triangles out of range of ", v, " vertices");
  if (mesh.pinJoints.size() != mesh.pinnedVertices.size() ||
      (!mesh.pinOffsets.empty() && mesh.pinOffsets.size() != mesh.pinnedVertices.size()) ||
      std::any_of(mesh.pinnedVertices.begin(), mesh.pinnedVertices.end(),
                  [&](uint32_t i) { return i >= v; }))
    fail(r.name(), ": mesh pins inconsistent");
  return mesh;
}

void addSecondaryGraphChunks(ChunkWriter& w, const SecondaryGraph& g) {
  std::vector<uint32_t> targets;
  std::vector<uint8_t> merges;
  std::vector<float> errors;
  for (const SecondaryEdge& e : g.edges) {
    targets.push_back(e.target);
    merges.push_back(uint8_t(e.isMerge ? 1 : 0));
    errors.push_back(e.error);
  }
  w.addScalar("SVTX", g.vertexCount);
  w.add("SNOD", g.stateNode);
  w.add("STGT", targets);
  w.add("SMRG", merges);
  w.add("SERR", errors);
  w.addView("SPOS", std::span<const glm::vec3>(g.positions));
  w.addView("SVEL", std::span<const glm::vec3>(g.velocities));
  w.add("SQUE", std::vector<MergeKey>(g.queue.begin(), g.queue.end()));
  w.add("SHIS", g.history);
  const uint64_t counters[2] = {g.expansions, g.simulatedSteps};
  w.add("SCNT", std::span<const uint64_t>(counters));
}

SecondaryGraph readSecondaryGraphChunks(const ChunkReader& r, const PrimaryGraph& primary) {
  SecondaryGraph g = makeSecondaryGraph(primary, r.scalar<uint32_t>("SVTX"));
  g.stateNode = r.vector<uint32_t>("SNOD");
  const uint64_t states = g.stateNode.size();
  const uint64_t edges = edgeCountFor(r, g.stateNode, primary);
  for (const char* tag : {"STGT", "SMRG", "SERR"}) r.expectCount(r.require(tag), edges);
  for (const char* tag : {"SPOS", "SVEL"}) r.expectCount(r.require(tag), states * g.vertexCount);
  const std::vector<uint32_t> targets = r.vector<uint32_t>("STGT");
  const std::vector<uint8_t> merges = r.vector<uint8_t>("SMRG");
  const std::vector<float> errors = r.vector<float>("SERR");
  g.edges.resize(edges);
  for (size_t i = 0; i < edges; ++i) g.edges[i] = {targets[i], merges[i] ? 1u : 0u, errors[i]};
  g.firstEdge.assign(1, 0);
  for (uint32_t node : g.stateNode)
    g.firstEdge.push_back(g.firstEdge.back() + uint32_t(primary.successors[node].size()));
  g.positions = r.vector<glm::vec3>("SPOS");
  g.velocities = r.vector<glm::vec3>("SVEL");
  g.history = r.vector<ErrorSample>("SHIS");
  const std::vector<uint64_t> counters = r.vector<uint64_t>("SCNT");
  r.expectCount(r.require("SCNT"), 2);
  g.expansions = counters[0];
  g.simulatedSteps = counters[1];
  try {
    rebuildIndexes(g, primary);
    validateGraph(g, primary, true);
  } catch (const Error& e) {
    fail(r.name(), ": inconsistent secondary graph: ", e.what());
  }
  const std::vector<MergeKey> queue = r.vector<MergeKey>("SQUE");
  if (queue.size() != g.queue.size() || !std::equal(queue.begin(), queue.end(), g.queue.begin(),
                                                    [](const MergeKey& a, const MergeKey& b) {
                                                      return a.state == b.state &&
                                                             a.edge == b.edge && a.error == b.error;
                                                    }))
    fail(r.name(), ": stored merge queue does not match the merge edges");
  return g;
}

void saveExploreFile(const std::filesystem::path& path, const nlohmann::json& config,
                     const PrimaryGraph& primary, const ClothMesh& mesh,
                     const SecondaryGraph& graph, const ClipPairIdentity& clips) {
  ChunkWriter w(kTsgMagic, kTsgVersion);
  w.addString("CONF", config.dump());
  addClipIdentityChunks(w, clips);
  addPrimaryGraphChunks(w, primary);
  addClothMeshChunks(w, mesh);
  addSecondaryGraphChunks(w, graph);
  w.writeFileAtomic(path);
}

ExploreFile loadExploreFile(const std::filesystem::path& path) {
  const ChunkReader r = openTsg(path);
  ExploreFile f;
  f.config = readConfig(r);
  f.primary = readPrimaryGraphChunks(r);
  f.mesh = readClothMeshChunks(r);
  f.graph = readSecondaryGraphChunks(r, f.primary);
  if (f.graph.vertexCount != f.mesh.vertexCount())
    fail(r.name(), ": frames of ", f.graph.vertexCount, " vertices for a mesh of ",
         f.mesh.vertexCount());
  for (uint32_t joint : f.mesh.pinJoints)
    if (joint >= f.primary.jointCount)
      fail(r.name(), ": a cloth vertex is pinned to joint ", joint, " of a ", f.primary.jointCount,
           "-joint skeleton");
  f.clips = readClips(r, f.config, f.primary);
  if (f.clips.jointCount != f.primary.jointCount)
    fail(r.name(), ": the clip identity has ", f.clips.jointCount, " joints, the run graph ",
         f.primary.jointCount);
  return f;
}

nlohmann::json exploreFileInfo(const std::filesystem::path& path, bool withHistory) {
  const ChunkReader r = openTsg(path);
  const nlohmann::json config = readConfig(r);
  const PrimaryGraph primary = readPrimaryGraphChunks(r);
  const std::vector<uint32_t> stateNode = r.vector<uint32_t>("SNOD");
  const std::vector<uint32_t> targets = r.vector<uint32_t>("STGT");
  const std::vector<uint8_t> merges = r.vector<uint8_t>("SMRG");
  const std::vector<float> errors = r.vector<float>("SERR");
  r.expectCount(r.require("STGT"), edgeCountFor(r, stateNode, primary));
  r.expectCount(r.require("SMRG"), targets.size());
  r.expectCount(r.require("SERR"), targets.size());
  const std::vector<uint64_t> counters = r.vector<uint64_t>("SCNT");
  r.expectCount(r.require("SCNT"), 2);
  const std::vector<ErrorSample> history = r.vector<ErrorSample>("SHIS");

  std::vector<bool> covered(primary.nodes.size(), false);
  for (uint32_t n : stateNode) covered[n] = true;
  uint64_t deadEnds = 0, mergeCount = 0;
  float maxError = 0.0f;
  for (size_t i = 0; i < targets.size(); ++i) {
    deadEnds += targets[i] == kNoState;
    if (merges[i]) {
      ++mergeCount;
      maxError = std::max(maxError, errors[i]);
    }
  }
  nlohmann::json j;
  j["file"] = path.string();
  j["kind"] = "secondary graph";
  j["format_version"] = r.version();
  j["bytes"] = r.totalBytes();
  j["garment"] = garmentName(config);
  const ClipPairIdentity clips = readClips(r, config, primary);
  j["clips"] = clips.name;
  j["clips_identity"] = clips.describe();
  j["config"] = config;
  j["states"] = stateNode.size();
  j["frames"] = stateNode.size();
  j["vertices"] = r.scalar<uint32_t>("SVTX");
  j["primary_nodes"] = primary.nodes.size();
  j["primary_nodes_with_states"] = std::count(covered.begin(), covered.end(), true);
  j["edges"] = targets.size();
  j["merge_edges"] = mergeCount;
  j["dead_ends"] = deadEnds;
  j["max_merge_error_m"] = maxError;
  j["expansions"] = counters[0];
  j["simulated_steps"] = counters[1];
  j["frame_bytes"] = r.require("SPOS").payloadBytes() + r.require("SVEL").payloadBytes();
  if (withHistory) {
    nlohmann::json h = nlohmann::json::array();
    for (const ErrorSample& s : history)
      h.push_back({{"expansions", s.expansions},
                   {"frames", s.states},
                   {"simulated_steps", s.simulatedSteps},
                   {"max_merge_error_m", s.maxMergeError}});
    j["error_history"] = h;
  }
  return j;
}

}  // namespace throng::secondary
