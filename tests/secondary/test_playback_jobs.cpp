// The playback jobs' validity cases: each names what is missing or inconsistent.
#include <doctest/doctest.h>

#include "core/error.h"
#include "playback_gpu_fixtures.h"

using namespace throng;
using namespace throng::secondary;

namespace {
bool mentions(const std::vector<std::string>& problems, const std::string& what) {
  for (const std::string& p : problems)
    if (p.find(what) != std::string::npos) return true;
  return false;
}
}  // namespace

TEST_CASE("cloth jobs: empty jobs list every missing input") {
  CHECK(mentions(ClothAdvanceJob{}.validate(), "'crowd'"));
  CHECK(mentions(ClothAdvanceJob{}.validate(), "'cloth'"));
  CHECK(mentions(ClothAdvanceJob{}.validate(), "'buffers'"));
  CHECK(mentions(ClothMarkJob{}.validate(), "'view'"));
  CHECK(mentions(ClothDecodeJob{}.validate(), "'cloth'"));
  CHECK(mentions(ClothDrawJob{}.validate(), "'view'"));
}

TEST_CASE("cloth jobs: a crowd of another size and a smaller database are refused at record") {
  PlaybackPrimary p = test::syntheticPrimary(0.5f, {4, 4, 4});
  ClothDatabase db =
      test::randomDatabase(p, test::syntheticGraph(p, 2), test::gridMesh(5, 4), 4, 1);
  std::vector<glm::vec4> placement(8, glm::vec4(0.0f)),
      motion(8, glm::vec4(0.1f, 0.5f, 0.5f, 1.0f));
  test::ClothGpuRun run(db, placement, motion);
  CHECK(run.advanceJob().validate().empty());
  CHECK(run.markJob().validate().empty());
  CHECK(run.decodeJob().validate().empty());
  CHECK(run.drawJob().validate().empty());

  crowd::Crowd other;
  other.resize(5);
  crowd::CrowdBuffers otherBuffers = crowd::uploadCrowd(test::gpuContext(), other);
  ClothAdvanceJob advance = run.advanceJob();
  advance.crowd = &otherBuffers;
  CHECK(mentions(advance.validate(),
                 "the crowd has 5 characters, the cloth buffers were made for 8"));
  CHECK_THROWS_WITH_AS(
      gpu::submitAndWait(test::gpuContext(),
                         [&](VkCommandBuffer cmd) { advance.record(cmd, *run.programs); }),
      doctest::Contains("ClothAdvanceJob is invalid"), Error);

  ClothDatabase bigger =
      test::randomDatabase(p, test::syntheticGraph(p, 3), test::gridMesh(5, 4), 4, 1);
  ClothGpuData biggerData = uploadCloth(test::gpuContext(), bigger);
  ClothDecodeJob decode = run.decodeJob();
  decode.cloth = &biggerData;
  CHECK(mentions(decode.validate(), "smaller database"));
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

TEST_CASE("cloth splat job: the visibility buffer and a splat program are required") {
  PlaybackPrimary p = test::syntheticPrimary(0.5f, {4, 4, 4});
  ClothDatabase db =
      test::randomDatabase(p, test::syntheticGraph(p, 2), test::gridMesh(32, 24), 4, 1);
  std::vector<glm::vec4> placement(4, glm::vec4(0.0f)),
      motion(4, glm::vec4(0.1f, 0.5f, 0.5f, 1.0f));
  test::ClothGpuRun run(db, placement, motion);
  run.setCamera(render::Camera{}, 64, 48, {});
  ClothSplatJob splat{&run.cloth, &run.crowdBuffers, &run.buffers, &run.view, nullptr};
  CHECK(mentions(splat.validate(), "'visibility'"));
  gpu::Buffer small(test::gpuContext(), 64 * 8, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  splat.visibility = &small;
  CHECK(mentions(splat.validate(), "holds 64 pixels, the view has 3072"));
  // A garment whose coarsest level is too large to splat gets no splat program.
  ClothDatabase big = test::randomDatabase(p, test::syntheticGraph(p, 1),
                                           test::gridMesh(128, 96, 4.0f, 6.0f), 2, 1);
  ClothGpuData bigData = uploadCloth(test::gpuContext(), big);
  CHECK_FALSE(clothSplattable(bigData));
  splat.cloth = &bigData;
  CHECK(mentions(splat.validate(), "no splat program"));
}
