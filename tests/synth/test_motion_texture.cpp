// Motion textures: the layout of docs/design.md baked from a clip, uploaded as a Vulkan image and read
// back through texelFetch in a compute shader, with the parent array SSBO.
#include <doctest/doctest.h>

#include "anim/default_clips.h"
#include "core/error.h"
#include "anim/motion_texture.h"
#include "gpu/commands.h"
#include "gpu/program.h"
#include "gpu_fixture.h"
#include "shaders/synth_bindings.h"
#include "synth/motion_gpu.h"
#include "test_support.h"

using namespace throng;

namespace {
void checkRoundTrip(const anim::MotionPair& pair) {
  gpu::Context& ctx = test::gpuContext();
  synth::GpuMotionPair gpuPair = synth::uploadMotionPair(ctx, pair);
  gpu::ComputeProgram program(ctx, "texel_readback.comp");
  for (const auto* tex : {&pair.slow, &pair.fast}) {
    const gpu::Image2D& image = tex == &pair.slow ? gpuPair.slow : gpuPair.fast;
    CHECK(image.width() == uint32_t(2 * pair.jointCount()));
    CHECK(image.height() == uint32_t(tex->frameCount));
    const uint32_t count = image.width() * image.height();
    gpu::Buffer texels(ctx, count * sizeof(glm::vec4), gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
    gpu::Buffer parents(ctx, pair.parents.size() * sizeof(int32_t), gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
    struct Push {
      uint32_t width, height, jointCount;
    } push{image.width(), image.height(), uint32_t(pair.jointCount())};
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      gpu::Binding bindings[] = {
          gpu::sampledImageBinding(gpu_types::kTexelReadbackBindingTexture, image.view(),
                                   gpuPair.sampler),
          gpu::storageBinding(gpu_types::kTexelReadbackBindingParents, gpuPair.parents),
          gpu::storageBinding(gpu_types::kTexelReadbackBindingTexels, texels),
          gpu::storageBinding(gpu_types::kTexelReadbackBindingParentsOut, parents)};
      gpu::dispatch(cmd, program, bindings, push, count);
    });
    auto read = gpu::readback<glm::vec4>(ctx, texels, count);
    for (int f = 0; f < tex->frameCount; ++f) {
      for (int j = 0; j < pair.jointCount(); ++j) {
        REQUIRE(read[size_t(f) * image.width() + 2 * j] == tex->rotation(f, j));
        REQUIRE(glm::vec3(read[size_t(f) * image.width() + 2 * j + 1]) == tex->offset(f, j));
      }
    }
    CHECK(gpu::readback<int32_t>(ctx, parents, pair.parents.size()) == pair.parents);
  }
  CHECK(ctx.validationMessageCount() == 0);
}
}  // namespace

TEST_CASE("motion texture: layout of docs/design.md (rotation at 2j, offset at 2j+1, root position)") {
  anim::ClipPair clips = anim::defaultRunPair();
  anim::MotionTexture tex = anim::bakeMotionTexture(clips.slow);
  CHECK(tex.width() == 2 * clips.slow.jointCount());
  CHECK(tex.frameCount == clips.slow.frameCount);
  for (int f : {0, 7, tex.frameCount - 1}) {
    CHECK(tex.rotation(f, 3) == clips.slow.rotation(f, 3));
    CHECK(tex.offset(f, 0) == clips.slow.rootPositions[f]);
    CHECK(tex.offset(f, 5) == clips.slow.skeleton.joints[5].offset);
    CHECK(glm::length(tex.rotation(f, 3)) == doctest::Approx(1.0f).epsilon(1e-5));
  }
  CHECK(tex.cycleTravel == clips.slow.cycleTravel);
}

TEST_CASE("motion texture: a pair with different topologies is refused") {
  anim::ClipPair clips = anim::defaultRunPair();
  anim::Clip other = clips.fast;
  other.skeleton.joints[5].parent = 1;
  CHECK_THROWS_WITH_AS(anim::makeMotionPair(clips.slow, other), doctest::Contains("share one skeleton topology"), Error);
}

TEST_CASE("motion texture round trip through texelFetch: built-in run cycles") {
  anim::ClipPair clips = anim::defaultRunPair();
  checkRoundTrip(anim::makeMotionPair(clips.slow, clips.fast));
}

TEST_CASE("motion texture round trip through texelFetch: Bandai Namco run + dash") {
  if (!test::haveSharedData("bvh/bandai_namco")) return;
  auto dir = test::sharedDataDir() / "bvh/bandai_namco";
  anim::ClipPair clips = anim::loadClipPair(dir / "dataset-1_run_normal_001.bvh", dir / "dataset-1_dash_normal_001.bvh");
  checkRoundTrip(anim::makeMotionPair(clips.slow, clips.fast));
}
