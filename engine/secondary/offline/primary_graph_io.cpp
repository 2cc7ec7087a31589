// The primary graph on disk: chunks of binary_io.h (versioned, checksummed, atomic writes).
#include <numeric>

#include "core/binary_io.h"
#include "core/error.h"
#include "secondary/offline/primary_graph.h"

namespace throng::secondary {
namespace {
constexpr std::string_view kMagic = "THRPRIMG";
constexpr uint32_t kVersion = 1;
constexpr std::string_view kKind = "primary motion graph";
}  // namespace

void addPrimaryGraphChunks(ChunkWriter& writer, const PrimaryGraph& graph) {
  validatePrimaryGraph(graph);
  writer.addScalar("PFRT", graph.frameTime);
  writer.addScalar("PJNT", graph.jointCount);
  writer.add("PPAR", graph.parents);
  std::string names;
  for (const std::string& name : graph.jointNames) {
    if (name.find('\n') != std::string::npos)
      fail("primary graph: joint name '", name, "' holds a newline");
    names += name + '\n';
  }
  writer.addString("PNAM", names);
  std::vector<uint32_t> nodes, counts, targets;
  std::vector<glm::vec3> positions, steps;
  std::vector<glm::vec4> rotations;
  for (const PrimaryNode& n : graph.nodes) nodes.insert(nodes.end(), {n.clip, n.bucket, n.frame});
  for (const NodeJoint& j : graph.poses) {
    positions.push_back(j.position);
    rotations.push_back(j.rotation);
  }
  for (size_t v = 0; v < graph.nodes.size(); ++v) {
    counts.push_back(uint32_t(graph.successors[v].size()));
    targets.insert(targets.end(), graph.successors[v].begin(), graph.successors[v].end());
    steps.insert(steps.end(), graph.rootStep[v].begin(), graph.rootStep[v].end());
  }
  writer.add("PNOD", nodes);
  writer.add("PPOS", positions);
  writer.add("PROT", rotations);
  writer.add("PSCN", counts);
  writer.add("PSUC", targets);
  writer.add("PSTP", steps);
}

PrimaryGraph readPrimaryGraphChunks(const ChunkReader& reader) {
  PrimaryGraph graph;
  graph.frameTime = reader.scalar<float>("PFRT");
  graph.jointCount = reader.scalar<uint32_t>("PJNT");
  graph.parents = reader.vector<int32_t>("PPAR");
  const std::string names = reader.string("PNAM");
  for (size_t start = 0; start < names.size();) {
    const size_t end = names.find('\n', start);
    if (end == std::string::npos)
      fail(reader.name(), ": joint names chunk does not end with a newline");
    graph.jointNames.push_back(names.substr(start, end - start));
    start = end + 1;
  }
  const std::vector<uint32_t> nodes = reader.vector<uint32_t>("PNOD");
  if (nodes.size() % 3 != 0)
    fail(reader.name(), ": node chunk holds ", nodes.size(), " values, not triples");
  for (size_t i = 0; i < nodes.size(); i += 3)
    graph.nodes.push_back({nodes[i], nodes[i + 1], nodes[i + 2]});
  const size_t n = graph.nodes.size();
  reader.expectCount(reader.require("PPOS"), uint64_t(n) * graph.jointCount);
  reader.expectCount(reader.require("PROT"), uint64_t(n) * graph.jointCount);
  reader.expectCount(reader.require("PSCN"), n);
  const std::vector<glm::vec3> positions = reader.vector<glm::vec3>("PPOS");
  const std::vector<glm::vec4> rotations = reader.vector<glm::vec4>("PROT");
  for (size_t i = 0; i < positions.size(); ++i) graph.poses.push_back({positions[i], rotations[i]});
  const std::vector<uint32_t> counts = reader.vector<uint32_t>("PSCN");
  const uint64_t edges = std::accumulate(counts.begin(), counts.end(), uint64_t(0));
  reader.expectCount(reader.require("PSUC"), edges);
  reader.expectCount(reader.require("PSTP"), edges);
  const std::vector<uint32_t> targets = reader.vector<uint32_t>("PSUC");
  const std::vector<glm::vec3> steps = reader.vector<glm::vec3>("PSTP");
  size_t e = 0;
  for (size_t v = 0; v < n; ++v) {
    graph.successors.emplace_back(targets.begin() + ptrdiff_t(e),
                                  targets.begin() + ptrdiff_t(e + counts[v]));
    graph.rootStep.emplace_back(steps.begin() + ptrdiff_t(e),
                                steps.begin() + ptrdiff_t(e + counts[v]));
    e += counts[v];
  }
  try {
    validatePrimaryGraph(graph);
  } catch (const Error& error) {
    fail(reader.name(), ": ", error.what());
  }
  return graph;
}

std::vector<uint8_t> encodePrimaryGraph(const PrimaryGraph& graph) {
  ChunkWriter writer(kMagic, kVersion);
  addPrimaryGraphChunks(writer, graph);
  return writer.bytes();
}

PrimaryGraph decodePrimaryGraph(std::span<const uint8_t> bytes, const std::string& sourceName) {
  return readPrimaryGraphChunks(ChunkReader::fromBytes(
      std::vector<uint8_t>(bytes.begin(), bytes.end()), sourceName, kMagic, kVersion, kKind));
}

void savePrimaryGraph(const std::filesystem::path& path, const PrimaryGraph& graph) {
  ChunkWriter writer(kMagic, kVersion);
  addPrimaryGraphChunks(writer, graph);
  writer.writeFileAtomic(path);
}

PrimaryGraph loadPrimaryGraph(const std::filesystem::path& path) {
  return readPrimaryGraphChunks(ChunkReader::openFile(path, kMagic, kVersion, kKind));
}

}  // namespace throng::secondary
