// The CPU side of playback: graph tables, each character's traversal (edges, merges and their
// blend, skipped frames, jumps, speed changes), the garment LOD, and the mark twin.
#include <doctest/doctest.h>

#include <set>

#include "cloth_fixtures.h"
#include "playback_fixtures.h"
#include "secondary/cloth_decoder.h"
#include "secondary/cloth_lod.h"
#include "secondary/cloth_view.h"

using namespace throng;
using namespace throng::secondary;

namespace {
// Buckets 0, 0.5, 1 with 6, 5 and 4 frames; 2 states per node.
ClothDatabase database(uint32_t copies = 2) {
  PlaybackPrimary p = test::syntheticPrimary(0.5f, {6, 5, 4});
  return test::randomDatabase(p, test::syntheticGraph(p, copies), test::gridMesh(6, 5), 6, 3);
}
glm::vec4 motionAt(uint32_t frame, uint32_t frames, float w) {
  return {(float(frame) + 0.5f) / float(frames), w, w, 1.0f};
}
uint32_t nodeOf(const ClothDatabase& db, uint32_t bucket, uint32_t frame) {
  for (uint32_t n = 0; n < db.primary.nodeCount(); ++n)
    if (db.primary.nodes[n].bucket == bucket && db.primary.nodes[n].frame == frame) return n;
  return kNoNode;
}
uint32_t edgeTo(const ClothDatabase& db, uint32_t state, uint32_t node) {
  const PlaybackPrimary& p = db.primary;
  uint32_t from = db.graph.stateNode[state];
  for (uint32_t e = p.firstSuccessor[from]; e < p.firstSuccessor[from + 1]; ++e)
    if (p.successors[e] == node) return db.graph.firstEdge[state] + e - p.firstSuccessor[from];
  FAIL("no edge");
  return 0;
}
}  // namespace

TEST_CASE("playback tables: run nodes, first states, natural successors") {
  ClothDatabase db = database();
  PlaybackTables t = makePlaybackTables(db);
  CHECK(t.bucketCount == 3);
  CHECK(t.runFirst == std::vector<uint32_t>{0, 6, 11, 15});
  for (uint32_t b = 0; b < 3; ++b)
    for (uint32_t f = 0; f < db.primary.run.framesPerBucket[b]; ++f)
      CHECK(t.runNodes[t.runFirst[b] + f] == nodeOf(db, b, f));
  for (uint32_t n = 0; n < db.primary.nodeCount(); ++n) CHECK(t.firstStateAtNode[n] == 2 * n);
  // Mid-cycle: the only successor; cycle end: the successor that is frame 0 of the same bucket.
  CHECK(t.naturalSuccessor[nodeOf(db, 0, 2)] == 0);
  CHECK(t.naturalSuccessor[nodeOf(db, 0, 5)] == 0);
  CHECK(t.naturalSuccessor[nodeOf(db, 1, 4)] == 1);
  CHECK(t.naturalSuccessor[nodeOf(db, 2, 3)] == 2);
  CHECK(characterNode(db, t, motionAt(3, 5, 0.45f)) == nodeOf(db, 1, 3));
  CHECK(characterNode(db, t, {0.999999f, 1.0f, 1.0f, 1.0f}) == nodeOf(db, 2, 3));
  CHECK(characterNode(db, t, {0.0f, 0.2f, 0.2f, 1.0f}) == nodeOf(db, 0, 0));
}

TEST_CASE("traversal: first frame, edges, merges blend over kMergeBlendFrames") {
  ClothDatabase db = database();
  PlaybackTables t = makePlaybackTables(db);
  ClothCharacter c = noClothCharacter();
  advanceCharacter(db, t, c, motionAt(0, 6, 0.0f));
  CHECK(c.node == nodeOf(db, 0, 0));
  CHECK(c.state == t.firstStateAtNode[c.node]);
  CHECK(c.countdown == 0);
  // Same node: nothing moves.
  ClothCharacter before = c;
  advanceCharacter(db, t, c, motionAt(0, 6, 0.0f));
  CHECK(c.state == before.state);
  // Along the cycle: copy 0 keeps copy 0 on successor 0 (a simulated edge).
  for (uint32_t f = 1; f < 6; ++f) {
    uint32_t expected = db.graph.edgeTarget[edgeTo(db, c.state, nodeOf(db, 0, f))];
    advanceCharacter(db, t, c, motionAt(f, 6, 0.0f));
    CHECK(c.state == expected);
    CHECK(c.node == nodeOf(db, 0, f));
    CHECK(c.countdown == 0);
  }
  // Cycle end into bucket 1 = successor 1: copy 0 → copy 1, a merge.
  uint32_t from = c.state;
  uint32_t edge = edgeTo(db, from, nodeOf(db, 1, 0));
  REQUIRE(db.graph.edgeIsMerge[edge] == 1);
  advanceCharacter(db, t, c, motionAt(0, 5, 0.5f));
  CHECK(c.state == db.graph.edgeTarget[edge]);
  CHECK(c.blendSource == from);
  CHECK(c.countdown == kMergeBlendFrames);
  CHECK(blendSourceWeight(c) == doctest::Approx(10.0f / 11.0f));
  // The blend runs out one primary frame at a time.
  advanceCharacter(db, t, c, motionAt(1, 5, 0.5f));
  CHECK(c.countdown == kMergeBlendFrames - 1);
  advanceCharacter(db, t, c, motionAt(1, 5, 0.5f));
  CHECK(c.countdown == kMergeBlendFrames - 1);
}

TEST_CASE("traversal: skipped frames are walked, jumps go to the first state with a blend") {
  ClothDatabase db = database(3);
  PlaybackTables t = makePlaybackTables(db);
  ClothCharacter c = noClothCharacter();
  advanceCharacter(db, t, c, motionAt(1, 6, 0.0f));
  uint32_t s = c.state;
  uint32_t s2 = db.graph.edgeTarget[edgeTo(db, s, nodeOf(db, 0, 2))];
  uint32_t s3 = db.graph.edgeTarget[edgeTo(db, s2, nodeOf(db, 0, 3))];
  advanceCharacter(db, t, c, motionAt(3, 6, 0.0f));  // frame 2 was dropped
  CHECK(c.state == s3);
  CHECK(c.node == nodeOf(db, 0, 3));
  // Frames 4 and 5 dropped across the cycle end into bucket 2: walked to (0, 5), then the edge.
  uint32_t s4 = db.graph.edgeTarget[edgeTo(db, s3, nodeOf(db, 0, 4))];
  uint32_t s5 = db.graph.edgeTarget[edgeTo(db, s4, nodeOf(db, 0, 5))];
  uint32_t s6 = db.graph.edgeTarget[edgeTo(db, s5, nodeOf(db, 2, 0))];
  advanceCharacter(db, t, c, motionAt(0, 4, 1.0f));
  CHECK(c.state == s6);
  CHECK(c.node == nodeOf(db, 2, 0));
  // Further than kMaxWalkSteps natural steps is a jump: the first state there, blended from where
  // it was. (2, 0) → (0, 4) and then one frame back, (0, 4) → (0, 3).
  // A jump starts a blend from where the cape was unless one is under way (which then goes on).
  for (uint32_t target : {4u, 3u}) {
    const ClothCharacter before = c;
    CHECK(advanceCharacter(db, t, c, motionAt(target, 6, 0.0f)));
    CHECK(c.node == nodeOf(db, 0, target));
    CHECK(c.state == t.firstStateAtNode[nodeOf(db, 0, target)]);
    if (before.countdown > 0) {
      CHECK(c.blendSource == before.blendSource);
      CHECK(c.countdown == before.countdown - 1);
    } else {
      CHECK(c.blendSource == before.state);
      CHECK(c.countdown == kMergeBlendFrames);
    }
  }
  // After the blend has run out, a jump blends from the state left behind.
  c.countdown = 0;
  const uint32_t here = c.state;
  CHECK(advanceCharacter(db, t, c, motionAt(2, 5, 0.5f)));  // (0, 3) → (1, 2): 5 frames on
  CHECK(c.state == t.firstStateAtNode[nodeOf(db, 1, 2)]);
  CHECK(c.blendSource == here);
  CHECK(c.countdown == kMergeBlendFrames);
}

TEST_CASE("traversal: a merge while a blend is under way lets that blend go on") {
  // Two copies per node: bucket 1's cycle end back into bucket 1 (successor 1) is a merge for
  // copy 1, and so is bucket 0's cycle end into bucket 1 for copy 0.
  ClothDatabase db = database(2);
  PlaybackTables t = makePlaybackTables(db);
  ClothCharacter c = noClothCharacter();
  for (uint32_t f = 0; f < 6; ++f) CHECK_FALSE(advanceCharacter(db, t, c, motionAt(f, 6, 0.0f)));
  const uint32_t left = c.state;
  CHECK(advanceCharacter(db, t, c, motionAt(0, 5, 0.5f)));  // merge: the blend starts
  CHECK(c.blendSource == left);
  CHECK(c.countdown == kMergeBlendFrames);
  for (uint32_t f = 1; f < 5; ++f) CHECK_FALSE(advanceCharacter(db, t, c, motionAt(f, 5, 0.5f)));
  CHECK(c.countdown == kMergeBlendFrames - 4);
  const uint32_t edge = edgeTo(db, c.state, nodeOf(db, 1, 0));
  REQUIRE(db.graph.edgeIsMerge[edge] == 1);
  CHECK(advanceCharacter(db, t, c, motionAt(0, 5, 0.5f)));  // a second merge, mid-blend
  CHECK(c.state == db.graph.edgeTarget[edge]);
  CHECK(c.blendSource == left);  // still blending from what the cape showed
  CHECK(c.countdown == kMergeBlendFrames - 5);
}

TEST_CASE("traversal: a character that changes speed moves to the state of the new bucket's edge") {
  ClothDatabase db = database(2);
  PlaybackTables t = makePlaybackTables(db);
  for (uint32_t newBucket = 0; newBucket < 3; ++newBucket) {
    ClothCharacter c = noClothCharacter();
    for (uint32_t f = 0; f < 5; ++f) advanceCharacter(db, t, c, motionAt(f, 5, 0.5f));
    REQUIRE(c.node == nodeOf(db, 1, 4));
    uint32_t expected = db.graph.edgeTarget[edgeTo(db, c.state, nodeOf(db, newBucket, 0))];
    float w = 0.5f * float(newBucket);
    advanceCharacter(db, t, c, {0.01f, w, w, 1.0f});
    CHECK(c.node == nodeOf(db, newBucket, 0));
    CHECK(c.state == expected);
    CHECK(db.graph.stateNode[c.state] == c.node);
  }
}

TEST_CASE("traversal: states always sit at the character's node over a long random run") {
  ClothDatabase db = database(3);
  PlaybackTables t = makePlaybackTables(db);
  test::MotionSim sim{db.primary.run};
  sim.init(300, 5);
  std::vector<ClothCharacter> chars(300, noClothCharacter());
  for (int frame = 0; frame < 120; ++frame) {
    for (size_t i = 0; i < chars.size(); ++i) {
      advanceCharacter(db, t, chars[i], sim.motion[i]);
      REQUIRE(chars[i].node == characterNode(db, t, sim.motion[i]));
      REQUIRE(db.graph.stateNode[chars[i].state] == chars[i].node);
      REQUIRE(chars[i].countdown <= kMergeBlendFrames);
    }
    sim.step();
  }
}

TEST_CASE("garment LOD: nested coarse-first levels, valid triangles and remap") {
  PlaybackPrimary primary = test::syntheticPrimary(0.5f, {6, 5, 4});
  ClothDatabase db =
      test::randomDatabase(primary, test::syntheticGraph(primary, 2), test::gridMesh(16, 12), 9, 4);
  ClothLod lod = buildClothLod(db);
  REQUIRE(lod.levelVertices.size() == kClothLevels);
  CHECK(lod.levelVertices[0] == db.vertexCount);
  CHECK(lod.levelVertices[1] < lod.levelVertices[0] / 2);
  CHECK(lod.levelVertices[2] < lod.levelVertices[1] / 2);
  CHECK(lod.levelVertices[3] < lod.levelVertices[2]);
  CHECK(lod.levelVertices[3] >= 4);
  CHECK(std::set<uint32_t>(lod.order.begin(), lod.order.end()).size() == db.vertexCount);
  CHECK(lod.indexCount[0] == db.triangles.size());
  CHECK(lod.levelBases == std::vector<uint32_t>{9, 9, 8, 4});
  for (uint32_t L = 0; L < kClothLevels; ++L) {
    CHECK(lod.indexCount[L] > 0);
    CHECK(lod.indexCount[L] % 3 == 0);
    for (uint32_t i = 0; i < lod.indexCount[L]; ++i)
      CHECK(lod.indices[lod.firstIndex[L] + i] < lod.levelVertices[L]);
    for (uint32_t k = 0; k < db.vertexCount; ++k) {
      uint32_t r = lod.remap[L * db.vertexCount + k];
      CHECK(r < lod.levelVertices[L]);
      if (k < lod.levelVertices[L]) CHECK(r == k);  // a representative stands for itself
    }
  }
  // Every decoded state lies inside the bounding sphere.
  DecodedBases d = dequantize(db);
  std::vector<glm::vec3> p(db.vertexCount);
  for (uint32_t s = 0; s < db.stateCount(); ++s) {
    decodeState(d, s, p);
    for (const glm::vec3& q : p) CHECK(glm::length(q - lod.center) <= lod.radius * 1.0001f);
  }
}

TEST_CASE("mark twin: culling, levels by size on screen, finest level per state") {
  ClothDatabase db = database();
  ClothLod lod = buildClothLod(db);
  render::Camera camera;
  camera.eye = {0.0f, 2.0f, -10.0f};
  camera.target = {0.0f, 1.0f, 0.0f};
  gpu_types::ClothView view = makeClothView(camera, 640, 480, lod, {true, 120.0f, 40.0f});
  std::vector<ClothCharacter> chars = {{0, 0, kNoClothState, 0}, {0, 0, 5, 3},
                                       {2, 1, kNoClothState, 0}, {4, 2, kNoClothState, 0},
                                       {6, 3, kNoClothState, 0}, noClothCharacter()};
  std::vector<glm::vec4> placement = {{0, 0, -7, 0},  {0.5f, 0, 0, 0}, {0, 0, 200, 0},
                                      {0, 0, -20, 0}, {400, 0, 0, 0},  {0, 0, 0, 0}};
  std::vector<glm::vec4> motion(6, glm::vec4(0.5f, 0.5f, 0.5f, 1.0f));
  CHECK(clothLevel(view, placement[0], 1.0f) == 0u);
  CHECK(clothLevel(view, placement[1], 1.0f) == 1u);
  CHECK(clothLevel(view, placement[2], 1.0f) == 3u);
  CHECK(clothLevel(view, placement[3], 1.0f) == gpu_types::kClothNone);  // behind the camera
  CHECK(clothLevel(view, placement[4], 1.0f) == gpu_types::kClothNone);  // far to the side
  ClothMarks marks =
      markCharacters(view, makePlaybackTables(db), db.stateCount(), chars, placement, motion);
  CHECK(marks.stateLevel[0] == 0);  // characters 0 (level 0) and 1 (level 1) share state 0
  CHECK(marks.stateLevel[5] == 1);  // character 1's blend source
  CHECK(marks.stateLevel[2] == 3);
  CHECK(marks.stateLevel[4] == gpu_types::kClothNone);
  CHECK(marks.usedStates == 3);
  CHECK(marks.drawLists[0] == std::vector<uint32_t>{0});
  CHECK(marks.drawLists[1] == std::vector<uint32_t>{1});
  CHECK(marks.drawLists[2].empty());
  CHECK(marks.drawLists[3] == std::vector<uint32_t>{2});
  // From level 2 on a cape shows its node's first state: a character far away in state 3 (node 1)
  // shows state 2, and never its blend source.
  std::vector<ClothCharacter> far = {{3, 1, 5, 4}};
  ClothMarks shared = markCharacters(view, makePlaybackTables(db), db.stateCount(), far,
                                     {&placement[2], 1}, motion);
  CHECK(shared.stateLevel[2] == 3);
  CHECK(shared.stateLevel[3] == gpu_types::kClothNone);
  CHECK(shared.stateLevel[5] == gpu_types::kClothNone);
  CHECK(shared.usedStates == 1);
  gpu_types::ClothView flat = makeClothView(camera, 640, 480, lod, {false, 120.0f, 40.0f});
  CHECK(clothLevel(flat, placement[2], 1.0f) == 0u);
}
