// The primary graph on disk: exact round trip, clear errors on damaged files.
#include <doctest/doctest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "primary_fixtures.h"

using namespace throng;
using namespace throng::secondary;

namespace {

void checkSame(const PrimaryGraph& a, const PrimaryGraph& b) {
  CHECK(a.frameTime == b.frameTime);
  CHECK(a.jointCount == b.jointCount);
  CHECK(a.parents == b.parents);
  CHECK(a.jointNames == b.jointNames);
  REQUIRE(a.nodes.size() == b.nodes.size());
  for (size_t i = 0; i < a.nodes.size(); ++i) {
    REQUIRE(a.nodes[i].clip == b.nodes[i].clip);
    REQUIRE(a.nodes[i].bucket == b.nodes[i].bucket);
    REQUIRE(a.nodes[i].frame == b.nodes[i].frame);
  }
  CHECK(a.successors == b.successors);
  CHECK(a.rootStep == b.rootStep);
  REQUIRE(a.poses.size() == b.poses.size());
  CHECK(std::memcmp(a.poses.data(), b.poses.data(), a.poses.size() * sizeof(NodeJoint)) == 0);
}

}  // namespace

TEST_CASE("a primary graph with a joined clip round-trips through a file bit for bit") {
  PrimaryGraph graph = *test::defaultRunGraph();
  addClipWithTransitions(graph, clipPoses(test::jogClip(), true), {});
  pruneToStronglyConnected(graph);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "throng_test_graph_io";
  std::filesystem::create_directories(dir);
  const std::filesystem::path path = dir / "run.tpg";
  savePrimaryGraph(path, graph);
  checkSame(graph, loadPrimaryGraph(path));
  checkSame(graph, decodePrimaryGraph(encodePrimaryGraph(graph), "memory"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("damaged primary graph files give a clear error") {
  const std::vector<uint8_t> bytes = encodePrimaryGraph(*test::standingGraph());
  std::vector<uint8_t> flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x40;
  CHECK_THROWS_AS(decodePrimaryGraph(flipped, "flipped"), Error);
  const std::vector<uint8_t> truncated(bytes.begin(), bytes.end() - 5);
  CHECK_THROWS_WITH_AS(decodePrimaryGraph(truncated, "truncated"), doctest::Contains("truncated"),
                       Error);
  std::vector<uint8_t> magic = bytes;
  magic[0] = 'X';
  CHECK_THROWS_WITH_AS(decodePrimaryGraph(magic, "magic"), doctest::Contains("magic"), Error);
  CHECK_THROWS_AS(loadPrimaryGraph("/nonexistent/graph.tpg"), Error);
  checkSame(*test::standingGraph(), decodePrimaryGraph(bytes, "intact"));
}
