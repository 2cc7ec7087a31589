// The far-cape splat against its CPU twin: the same pixels covered, with the same depth and
// colour (float rounding aside), into a visibility buffer like the joint renderer's.
#include <doctest/doctest.h>

#include <algorithm>

#include "playback_gpu_fixtures.h"
#include "secondary/cloth_splat_cpu.h"

using namespace throng;
using namespace throng::secondary;
using gpu_types::kClothSplatLevel;

namespace {
constexpr uint32_t kWidth = 320, kHeight = 200;
constexpr uint64_t kEmpty = ~uint64_t(0);

// A 32 × 24 cape grid: its splat level is small enough to splat.
ClothDatabase farDatabase() {
  PlaybackPrimary p = test::syntheticPrimary(0.5f, {6, 5, 4});
  ClothDatabase db =
      test::randomDatabase(p, test::syntheticGraph(p, 3), test::gridMesh(32, 24), 6, 8);
  for (QuantizedBasis& b : db.bases) {
    b.offset *= 0.1f;
    b.step *= 0.1f;
  }
  return db;
}
}  // namespace

TEST_CASE("splat: far capes cover the twin's pixels with its depth and colour") {
  ClothDatabase db = farDatabase();
  Rng rng(12);
  std::vector<glm::vec4> placement, motion;
  std::vector<ClothCharacter> characters;
  for (uint32_t i = 0; i < 400; ++i) {
    placement.push_back(
        {rng.uniform(-25.0f, 25.0f), 0.0f, rng.uniform(25.0f, 60.0f), rng.uniform(-3.1f, 3.1f)});
    motion.push_back({0.5f, 0.5f, 0.5f, rng.uniform(0.9f, 1.1f)});
    uint32_t state = rng.next() % db.stateCount();
    characters.push_back({state, db.graph.stateNode[state], kNoClothState, 0u});
  }
  test::ClothGpuRun run(db, placement, motion);
  REQUIRE(clothSplattable(run.cloth));
  render::Camera camera;
  camera.eye = {0.0f, 6.0f, -5.0f};
  camera.target = {0.0f, 1.0f, 40.0f};
  run.setCamera(camera, kWidth, kHeight,
                {true, 400.0f, 200.0f, 100.0f});  // everything at the splat level
  run.setCharacters(characters);
  gpu::Context& ctx = test::gpuContext();
  gpu::Buffer visibility(ctx, VkDeviceSize(kWidth) * kHeight * 8, gpu::kStorageUsage,
                         gpu::MemoryUse::DeviceLocal);
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, visibility.get(), 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);
    run.markJob().record(cmd, *run.programs);
    run.decodeJob().record(cmd, *run.programs);
    ClothSplatJob{&run.cloth, &run.crowdBuffers, &run.buffers, &run.view, &visibility}.record(
        cmd, *run.programs);
  });
  std::vector<uint64_t> gpuPixels =
      gpu::readback<uint64_t>(ctx, visibility, size_t(kWidth) * kHeight);

  ClothMarks marks = markCharacters(run.viewData, run.cloth.tables, db.stateCount(), characters,
                                    placement, motion);
  REQUIRE(marks.drawLists[kClothSplatLevel].size() > 200);
  CHECK(readClothStats(run.buffers).capes[kClothSplatLevel] ==
        marks.drawLists[kClothSplatLevel].size());
  DecodedBases decoded = dequantize(db);
  std::vector<uint64_t> cpuPixels(size_t(kWidth) * kHeight, kEmpty);
  SplatInputs in{&run.viewData,    &run.cloth.tables, &run.cloth.lod, &decoded,
                 marks.stateLevel, characters,        placement,      motion};
  splatCapesCpu(in, marks.drawLists[kClothSplatLevel], cpuPixels);

  size_t covered = 0, disagree = 0, colourOff = 0;
  for (size_t p = 0; p < cpuPixels.size(); ++p) {
    const bool a = gpuPixels[p] != kEmpty, b = cpuPixels[p] != kEmpty;
    covered += a || b;
    if (a != b) {
      ++disagree;
      continue;
    }
    if (!a) continue;
    float da, db2;
    uint32_t ba = uint32_t(gpuPixels[p] >> 32), bb = uint32_t(cpuPixels[p] >> 32);
    std::memcpy(&da, &ba, 4);
    std::memcpy(&db2, &bb, 4);
    CHECK(std::abs(da - db2) <= 1e-5f);
    for (int c = 0; c < 3; ++c) {
      int ca = int((gpuPixels[p] >> (8 * c)) & 255u), cb = int((cpuPixels[p] >> (8 * c)) & 255u);
      if (std::abs(ca - cb) > 2) ++colourOff;
    }
  }
  MESSAGE("covered pixels ", covered, ", coverage differs at ", disagree, ", colour differs at ",
          colourOff);
  CHECK(covered > 1000);
  CHECK(disagree <= covered / 100);   // edge pixels may round either way
  CHECK(colourOff <= covered / 100);  // where two capes meet at equal depth
  CHECK(ctx.validationMessageCount() == 0);
}
