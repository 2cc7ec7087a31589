// The mark and decode passes against their CPU twins: used states, levels, draw lists, and the
// decoded vertices (within 1e-4 m), also when the fine pool is full and states are demoted.
#include <doctest/doctest.h>

#include <algorithm>

#include "playback_gpu_fixtures.h"
#include "secondary/cloth_decoder.h"

using namespace throng;
using namespace throng::secondary;

namespace {
struct Scene {
  ClothDatabase db;
  std::vector<glm::vec4> placement, motion;
  std::vector<ClothCharacter> characters;
};

// Characters in a column receding from the camera (all three levels), some sharing states, some
// blending from another state, a few outside the view.
Scene scene(uint32_t characters) {
  PlaybackPrimary p = test::syntheticPrimary(0.5f, {6, 5, 4});
  Scene s{test::randomDatabase(p, test::syntheticGraph(p, 3), test::gridMesh(16, 12), 9, 21),
          {},
          {},
          {}};
  Rng rng(4);
  const uint32_t S = s.db.stateCount();
  for (uint32_t i = 0; i < characters; ++i) {
    float z = 0.5f + 120.0f * float(i) / float(characters);
    float x = (i % 7 == 6) ? 300.0f : rng.uniform(-0.3f, 0.3f) * z;
    s.placement.push_back({x, 0.0f, z, rng.uniform(-3.1f, 3.1f)});
    s.motion.push_back({0.5f, 0.5f, 0.5f, rng.uniform(0.8f, 1.2f)});
    uint32_t state = rng.next() % S;
    bool blending = i % 5 == 0;
    s.characters.push_back({state, s.db.graph.stateNode[state],
                            blending ? rng.next() % S : kNoClothState,
                            blending ? 1 + rng.next() % kMergeBlendFrames : 0u});
  }
  return s;
}

render::Camera camera() {
  render::Camera c;
  c.eye = {0.0f, 1.6f, -4.0f};
  c.target = {0.0f, 1.0f, 20.0f};
  return c;
}

struct GpuMarks {
  gpu_types::ClothCounters counters;
  std::vector<uint32_t> stateLevel, usedStates, drawList, draws;
  std::vector<glm::uvec2> slots;
  std::vector<float> pool;
};

GpuMarks runMarkAndDecode(test::ClothGpuRun& run) {
  gpu::Context& ctx = test::gpuContext();
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    run.markJob().record(cmd, *run.programs);
    run.decodeJob().record(cmd, *run.programs);
  });
  GpuMarks m;
  std::memcpy(&m.counters, run.buffers.counters.mapped(), sizeof(m.counters));
  m.stateLevel = gpu::readback<uint32_t>(ctx, run.buffers.stateLevel, run.cloth.stateCount);
  m.usedStates = gpu::readback<uint32_t>(
      ctx, run.buffers.usedStates, std::min(m.counters.usedStates, run.buffers.maxUsedStates));
  m.drawList = gpu::readback<uint32_t>(ctx, run.buffers.drawList,
                                       size_t(kClothLevels) * run.buffers.characterCount);
  m.draws = gpu::readback<uint32_t>(ctx, run.buffers.draws, kClothLevels * 5);
  m.slots = gpu::readback<glm::uvec2>(ctx, run.buffers.slots, run.cloth.stateCount);
  m.pool = gpu::readback<float>(ctx, run.buffers.pool, run.buffers.pool.size() / 4);
  return m;
}

// Largest distance between the GPU's decoded vertices of every used state and the CPU twin.
float compareDecode(const test::ClothGpuRun& run, const GpuMarks& m, const ClothMarks& cpu,
                    uint32_t* demoted) {
  const ClothLod& lod = run.cloth.lod;
  DecodedBases decoded = dequantize(*run.db);
  float worst = 0.0f;
  *demoted = 0;
  for (uint32_t s : m.usedStates) {
    glm::uvec2 slot = m.slots[s];
    CHECK(slot.y >= cpu.stateLevel[s]);
    if (slot.y != cpu.stateLevel[s]) ++*demoted;
    const uint32_t n = lod.levelVertices[slot.y];
    std::vector<glm::vec3> expected(n);
    decodeStateSubset(decoded, s, lod.order, lod.levelBases[slot.y], expected);
    for (uint32_t k = 0; k < n; ++k) {
      const float* p = &m.pool[3 * (size_t(slot.x) + k)];
      worst = std::max(worst, glm::length(glm::vec3(p[0], p[1], p[2]) - expected[k]));
    }
  }
  return worst;
}
}  // namespace

TEST_CASE(
    "mark + decode: used states, levels and draw lists match the twin; decode within 1e-4 m") {
  Scene s = scene(600);
  test::ClothGpuRun run(s.db, s.placement, s.motion);
  run.setCamera(camera(), 800, 600, {true, 120.0f, 40.0f, 15.0f});
  run.setCharacters(s.characters);
  GpuMarks m = runMarkAndDecode(run);
  ClothMarks cpu = markCharacters(run.viewData, run.cloth.tables, s.db.stateCount(), s.characters,
                                  s.placement, s.motion);

  CHECK(m.counters.usedStates == cpu.usedStates);
  CHECK(m.stateLevel == cpu.stateLevel);
  std::vector<uint32_t> used = m.usedStates, expectedUsed;
  std::sort(used.begin(), used.end());
  for (uint32_t st = 0; st < s.db.stateCount(); ++st)
    if (cpu.stateLevel[st] != gpu_types::kClothNone) expectedUsed.push_back(st);
  CHECK(used == expectedUsed);
  for (uint32_t L = 0; L < kClothLevels; ++L) {
    CHECK(!cpu.drawLists[L].empty());  // the scene exercises every level
    REQUIRE(m.draws[5 * L + 1] == cpu.drawLists[L].size());
    CHECK(m.draws[5 * L + 0] == run.cloth.lod.indexCount[L]);
    CHECK(m.draws[5 * L + 4] == L * 600);
    std::vector<uint32_t> list(m.drawList.begin() + L * 600,
                               m.drawList.begin() + L * 600 + cpu.drawLists[L].size());
    std::sort(list.begin(), list.end());
    CHECK(list == cpu.drawLists[L]);
  }
  uint32_t demoted = 0;
  CHECK(compareDecode(run, m, cpu, &demoted) <= 1e-4f);
  CHECK(demoted == 0);
  CHECK(m.counters.demoted == 0);

  // A second frame after moving the camera: the counters were reset and everything agrees again.
  render::Camera closer = camera();
  closer.eye.z = 40.0f;
  run.setCamera(closer, 800, 600, {true, 120.0f, 40.0f, 15.0f});
  m = runMarkAndDecode(run);
  cpu = markCharacters(run.viewData, run.cloth.tables, s.db.stateCount(), s.characters, s.placement,
                       s.motion);
  CHECK(m.counters.usedStates == cpu.usedStates);
  CHECK(m.stateLevel == cpu.stateLevel);
  CHECK(compareDecode(run, m, cpu, &demoted) <= 1e-4f);
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

TEST_CASE("decode: a full fine pool demotes states to the coarsest level, still exact") {
  Scene s = scene(300);
  // Room for about three full-resolution states.
  test::ClothGpuRun run(s.db, s.placement, s.motion, 3 * 192 * 12);
  run.setCamera(camera(), 800, 600,
                {false, 0.0f, 0.0f, 0.0f});  // LOD off: every state wants level 0
  run.setCharacters(s.characters);
  GpuMarks m = runMarkAndDecode(run);
  ClothMarks cpu = markCharacters(run.viewData, run.cloth.tables, s.db.stateCount(), s.characters,
                                  s.placement, s.motion);
  uint32_t demoted = 0;
  CHECK(compareDecode(run, m, cpu, &demoted) <= 1e-4f);
  CHECK(m.counters.demoted == demoted);
  CHECK(demoted == m.counters.usedStates - 3);
  CHECK(test::gpuContext().validationMessageCount() == 0);
}
