// The advance pass against its twin: every character's traversal over many frames (dropped
// frames, speed changes at cycle ends, merges), and a character that changes speed.
#include <doctest/doctest.h>

#include "playback_fixtures.h"
#include "playback_gpu_fixtures.h"

using namespace throng;
using namespace throng::secondary;

namespace {
bool same(const ClothCharacter& a, const ClothCharacter& b) {
  return a.state == b.state && a.node == b.node && a.blendSource == b.blendSource &&
         a.countdown == b.countdown;
}

void advanceOnGpu(test::ClothGpuRun& run) {
  gpu::submitAndWait(test::gpuContext(),
                     [&](VkCommandBuffer cmd) { run.advanceJob().record(cmd, *run.programs); });
}
}  // namespace

TEST_CASE("advance: GPU traversal = CPU twin for 2,000 characters over 90 frames") {
  std::vector<uint32_t> frames;
  for (uint32_t b = 0; b < 21; ++b) frames.push_back(20 - b / 3);  // faster buckets: shorter cycles
  PlaybackPrimary p = test::syntheticPrimary(0.05f, frames);
  ClothDatabase db =
      test::randomDatabase(p, test::syntheticGraph(p, 3), test::gridMesh(4, 4), 3, 9);
  PlaybackTables tables = makePlaybackTables(db);
  test::MotionSim sim{db.primary.run};
  sim.init(2000, 17);
  std::vector<glm::vec4> placement(2000, glm::vec4(0.0f));
  test::ClothGpuRun run(db, placement, sim.motion);
  std::vector<ClothCharacter> cpu(2000, noClothCharacter());
  size_t mismatches = 0, merges = 0, bucketChanges = 0;
  for (int frame = 0; frame < 90; ++frame) {
    run.setMotion(sim.motion);
    advanceOnGpu(run);
    std::vector<uint32_t> before(2000);
    for (size_t i = 0; i < cpu.size(); ++i) {
      before[i] = cpu[i].node;
      advanceCharacter(db, tables, cpu[i], sim.motion[i]);
      if (cpu[i].countdown == kMergeBlendFrames) ++merges;
      if (before[i] != kNoNode &&
          db.primary.nodes[before[i]].bucket != db.primary.nodes[cpu[i].node].bucket)
        ++bucketChanges;
    }
    std::vector<ClothCharacter> gpuChars = run.characters();
    for (size_t i = 0; i < cpu.size(); ++i)
      if (!same(gpuChars[i], cpu[i])) ++mismatches;
    sim.step();
  }
  CHECK(mismatches == 0);
  CHECK(merges > 1000);        // the run crossed many merge edges (and jumps)
  CHECK(bucketChanges > 500);  // and many speed changes
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

TEST_CASE("advance: a character that changes speed moves to the right secondary state (GPU)") {
  PlaybackPrimary p = test::syntheticPrimary(0.5f, {6, 5, 4});
  ClothDatabase db =
      test::randomDatabase(p, test::syntheticGraph(p, 2), test::gridMesh(4, 4), 3, 9);
  PlaybackTables tables = makePlaybackTables(db);
  // Three characters on the last frame of bucket 0, each about to take another bucket.
  std::vector<glm::vec4> motion = {
      {5.5f / 6, 0.0f, 0.0f, 1.0f}, {5.5f / 6, 0.0f, 0.5f, 1.0f}, {5.5f / 6, 0.0f, 1.0f, 1.0f}};
  test::ClothGpuRun run(db, std::vector<glm::vec4>(3, glm::vec4(0.0f)), motion);
  advanceOnGpu(run);
  std::vector<ClothCharacter> start = run.characters();
  for (uint32_t i = 0; i < 3; ++i) {
    REQUIRE(start[i].node == tables.runNodes[5]);         // (bucket 0, frame 5)
    motion[i] = {0.02f, motion[i].z, motion[i].z, 1.0f};  // the cycle ended: w takes wTarget
  }
  run.setMotion(motion);
  advanceOnGpu(run);
  std::vector<ClothCharacter> after = run.characters();
  const uint32_t from = tables.runNodes[5];
  for (uint32_t i = 0; i < 3; ++i) {
    const uint32_t newNode = tables.runNodes[tables.runFirst[i]];  // frame 0 of bucket i
    uint32_t k = 0;
    while (db.primary.successors[db.primary.firstSuccessor[from] + k] != newNode) ++k;
    CHECK(after[i].node == newNode);
    CHECK(after[i].state == db.graph.edgeTarget[db.graph.firstEdge[start[i].state] + k]);
    CHECK(db.graph.stateNode[after[i].state] == newNode);
    const bool merge = db.graph.edgeIsMerge[db.graph.firstEdge[start[i].state] + k] != 0;
    CHECK(after[i].countdown == (merge ? kMergeBlendFrames : 0u));
  }
  CHECK(test::gpuContext().validationMessageCount() == 0);
}
