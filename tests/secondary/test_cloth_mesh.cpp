// Garment meshes: the cape hung from the neck and shoulders, the test square.
#include <doctest/doctest.h>

#include "core/error.h"
#include "core/math.h"
#include "primary_fixtures.h"
#include "secondary/offline/cloth_mesh.h"

using namespace throng;
using namespace throng::secondary;

TEST_CASE("the default cape: a pinned top row on the neck and shoulders, clear of the body") {
  const PrimaryGraph& graph = *test::defaultRunGraph();
  const ClothMesh cape = makeCape(graph);
  CHECK(cape.vertexCount() == 32 * 48);
  CHECK(cape.triangles.size() == size_t(31 * 47 * 2 * 3));
  for (uint32_t v : cape.triangles) REQUIRE(v < cape.vertexCount());
  REQUIRE(cape.pinnedVertices.size() == 32);
  REQUIRE(cape.pinJoints.size() == 32);
  REQUIRE(cape.pinOffsets.size() == 32);
  const std::vector<uint32_t> anchors = neckShoulderJoints(graph);
  const NodeJoint* pose = graph.pose(0);
  for (size_t k = 0; k < 32; ++k) {
    CHECK(cape.pinnedVertices[k] == k);
    CHECK(std::find(anchors.begin(), anchors.end(), cape.pinJoints[k]) != anchors.end());
    // The offset puts the pinned vertex back on its rest position at the rest pose.
    const NodeJoint& joint = pose[cape.pinJoints[k]];
    const glm::vec3 p = joint.position + quatRotate(joint.rotation, cape.pinOffsets[k]);
    CHECK(glm::length(p - cape.restPositions[k]) < 1e-5f);
  }
  // Both shoulders hold the cape (it is centred on the body).
  CHECK(graph.jointNames[cape.pinJoints.front()] == "RightShoulder");
  CHECK(graph.jointNames[cape.pinJoints.back()] == "LeftShoulder");
  // Hanging down the back: the hem is lower and further back than the top row.
  CHECK(cape.restPositions.back().y < cape.restPositions.front().y - 0.7f);
  CHECK(cape.restPositions.back().z < cape.restPositions.front().z);
  for (const CapsuleShape& c : capsulesAt(graph, resolveCapsules(graph, defaultBodyCapsules()), 0))
    for (const glm::vec3& p : cape.restPositions) REQUIRE(segmentDistance(p, c.a, c.b) >= c.radius);
}

TEST_CASE("cape options: resolution and size are honoured, nonsense is refused") {
  const PrimaryGraph& graph = *test::defaultRunGraph();
  const ClothMesh small = makeCape(graph, CapeOptions{.columns = 8, .rows = 12, .length = 0.5f});
  CHECK(small.vertexCount() == 96);
  CHECK(small.pinnedVertices.size() == 8);
  glm::vec3 top(0.0f), hem(0.0f);
  for (uint32_t c = 0; c < 8; ++c) {
    top += small.restPositions[c] / 8.0f;
    hem += small.restPositions[11 * 8 + c] / 8.0f;
  }
  CHECK(glm::length(hem - top) == doctest::Approx(0.5f).epsilon(1e-4));
  const float topWidth = glm::length(small.restPositions[7] - small.restPositions[0]);
  const float hemWidth = glm::length(small.restPositions[95] - small.restPositions[88]);
  CHECK(topWidth == doctest::Approx(0.36f).epsilon(1e-4));
  CHECK(hemWidth == doctest::Approx(0.36f * 1.4f).epsilon(1e-4));
  CHECK_THROWS_AS(makeCape(graph, CapeOptions{.columns = 1}), Error);
  CHECK_THROWS_AS(makeCape(graph, CapeOptions{.length = -1.0f}), Error);
  CHECK_THROWS_AS(makeCape(graph, CapeOptions{.node = 100000}), Error);
  CHECK_THROWS_WITH_AS(makeCape(*test::standingGraph()), doctest::Contains("neck or shoulder"),
                       Error);
}

TEST_CASE("the square cloth lies flat and hangs from its first row") {
  const ClothMesh square = makeSquareCloth(5, 2.0f);
  CHECK(square.vertexCount() == 25);
  CHECK(square.triangles.size() == size_t(4 * 4 * 2 * 3));
  CHECK(square.pinnedVertices == std::vector<uint32_t>{0, 1, 2, 3, 4});
  CHECK(square.pinOffsets[4] == glm::vec3(1.0f, 0.0f, 0.0f));
  CHECK(square.restPositions[24] == glm::vec3(1.0f, 0.0f, 2.0f));
  float area = 0.0f;
  for (size_t t = 0; t < square.triangles.size(); t += 3) {
    const glm::vec3 a = square.restPositions[square.triangles[t]],
                    b = square.restPositions[square.triangles[t + 1]],
                    c = square.restPositions[square.triangles[t + 2]];
    area += 0.5f * glm::length(glm::cross(b - a, c - a));
  }
  CHECK(area == doctest::Approx(4.0f));
  CHECK_THROWS_AS(makeSquareCloth(1, 1.0f), Error);
}
