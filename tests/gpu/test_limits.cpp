// Device limits: every buffer range, image size, allocation and dispatch is checked before it
// reaches Vulkan, and going past one is a LimitError naming the limit (never a validation
// error or undefined behaviour).
#include <doctest/doctest.h>

#include "gpu/buffer.h"
#include "gpu/commands.h"
#include "gpu/image.h"
#include "gpu/limits.h"
#include "gpu/program.h"
#include "gpu_fixture.h"
#include "shaders/synth_bindings.h"

using namespace throng;

namespace {
struct ScalePush {
  float scale;
  uint32_t count;
};
}  // namespace

TEST_CASE("limits: the device's limits are read into DeviceInfo") {
  const gpu::DeviceInfo& info = test::gpuContext().info();
  CHECK(info.maxStorageBufferRange >= 128u * 1024 * 1024);  // the Vulkan minimum is 2^27
  CHECK(info.maxUniformBufferRange >= 16384u);
  CHECK(info.maxImageDimension2D >= 4096u);
  CHECK(info.maxFramebufferWidth >= 4096u);
  CHECK(info.maxFramebufferHeight >= 4096u);
  CHECK(info.maxComputeWorkGroupCount[0] >= 65535u);
  CHECK(info.maxMemoryAllocationSize >= 1024u * 1024 * 1024);
}

TEST_CASE(
    "limits: a storage binding past maxStorageBufferRange is a LimitError, a range within it "
    "binds") {
  gpu::Context& ctx = test::gpuContext();
  const VkDeviceSize limit = ctx.info().maxStorageBufferRange;
  // NVIDIA's range is 4 GiB - 1 while one allocation may hold a little less than 4 GiB: no
  // buffer there is larger than the range, so nothing can bind past it.
  if (limit + 256 > ctx.info().maxMemoryAllocationSize) {
    MESSAGE("skipped: maxStorageBufferRange ", limit, " is not below maxMemoryAllocationSize ",
            ctx.info().maxMemoryAllocationSize);
    return;
  }
  gpu::ComputeProgram program(ctx, "test_scale.comp");
  gpu::Buffer big(ctx, limit + 256, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  gpu::Buffer out(ctx, 256, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  const uint32_t n = 64;
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    gpu::Binding whole[] = {gpu::storageBinding(gpu_types::kTestScaleBindingInput, big),
                            gpu::storageBinding(gpu_types::kTestScaleBindingOutput, out)};
    CHECK_THROWS_WITH_AS(gpu::dispatch(cmd, program, whole, ScalePush{1.0f, n}, n),
                         doctest::Contains("maxStorageBufferRange"), gpu::LimitError);
    gpu::Binding explicitRange[] = {
        gpu::storageBinding(gpu_types::kTestScaleBindingInput, big, 0, limit + 16),
        gpu::storageBinding(gpu_types::kTestScaleBindingOutput, out)};
    CHECK_THROWS_AS(gpu::dispatch(cmd, program, explicitRange, ScalePush{1.0f, n}, n),
                    gpu::LimitError);
    // A range past the end of its buffer is reported too.
    gpu::Binding overflow[] = {
        gpu::storageBinding(gpu_types::kTestScaleBindingInput, out, 128, 256),
        gpu::storageBinding(gpu_types::kTestScaleBindingOutput, out)};
    CHECK_THROWS_WITH_AS(gpu::dispatch(cmd, program, overflow, ScalePush{1.0f, n}, n),
                         doctest::Contains("overflows its buffer"), Error);
    // An offset off the device's alignment is reported before Vulkan sees it.
    const VkDeviceSize alignment = ctx.info().minStorageBufferOffsetAlignment;
    if (alignment > 1) {
      gpu::Binding misaligned[] = {
          gpu::storageBinding(gpu_types::kTestScaleBindingInput, big, alignment / 2, 256),
          gpu::storageBinding(gpu_types::kTestScaleBindingOutput, out)};
      CHECK_THROWS_WITH_AS(gpu::dispatch(cmd, program, misaligned, ScalePush{1.0f, n}, n),
                           doctest::Contains("minStorageBufferOffsetAlignment"), Error);
    }
    // The last `limit` bytes of the large buffer are a legal binding.
    gpu::Binding tail[] = {gpu::storageBinding(gpu_types::kTestScaleBindingInput, big, 256, limit),
                           gpu::storageBinding(gpu_types::kTestScaleBindingOutput, out)};
    gpu::dispatch(cmd, program, tail, ScalePush{1.0f, n}, n);
  });
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("limits: a dispatch past maxComputeWorkGroupCount is a LimitError") {
  gpu::Context& ctx = test::gpuContext();
  gpu::ComputeProgram program(ctx, "test_scale.comp");
  CHECK(program.maxGroupsX() == ctx.info().maxComputeWorkGroupCount[0]);
  gpu::Buffer in(ctx, 256, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  gpu::Buffer out(ctx, 256, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  gpu::Binding bindings[] = {gpu::storageBinding(gpu_types::kTestScaleBindingInput, in),
                             gpu::storageBinding(gpu_types::kTestScaleBindingOutput, out)};
  const uint64_t tooMany = uint64_t(program.maxGroupsX()) * program.localSizeX() + 1;
  if (tooMany > UINT32_MAX) {  // NVIDIA: 2^31 - 1 groups, more than a 32-bit count can ask for
    MESSAGE("skipped: ", program.maxGroupsX(), " groups of ", program.localSizeX(),
            " hold every 32-bit invocation count");
    return;
  }
  gpu::CommandPool pool(ctx);
  VkCommandBuffer cmd = pool.allocate();
  gpu::beginCommands(cmd);
  CHECK_THROWS_WITH_AS(gpu::dispatch(cmd, program, bindings, ScalePush{1.0f, 1}, uint32_t(tooMany)),
                       doctest::Contains("maxComputeWorkGroupCount[0]"), gpu::LimitError);
  gpu::endCommands(cmd);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("limits: an image past maxImageDimension2D is a LimitError before vkCreateImage") {
  gpu::Context& ctx = test::gpuContext();
  const uint32_t tooWide = ctx.info().maxImageDimension2D + 1;
  try {
    gpu::Image2D image(ctx, tooWide, 4, VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_SAMPLED_BIT);
    FAIL("no LimitError for a ", tooWide, "x4 image");
  } catch (const gpu::LimitError& e) {
    CHECK(e.limit() == "maxImageDimension2D");
    CHECK(e.needed() == tooWide);
    CHECK(e.allowed() == ctx.info().maxImageDimension2D);
    CHECK(std::string(e.what()).find(ctx.info().name) != std::string::npos);
  }
  CHECK_THROWS_AS(
      gpu::Image2D(ctx, 4, tooWide, VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT),
      gpu::LimitError);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("limits: an allocation past maxMemoryAllocationSize or its heap is a LimitError") {
  gpu::Context& ctx = test::gpuContext();
  const uint64_t tooLarge =
      std::max(ctx.info().maxMemoryAllocationSize, ctx.info().deviceLocalBytes) + 4096;
  VkMemoryRequirements requirements{tooLarge, 256, ~0u};
  CHECK_THROWS_WITH_AS(
      ctx.allocateMemory(requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, "a test allocation"),
      doctest::Contains("a test allocation needs"), gpu::LimitError);
  CHECK_THROWS_WITH_AS(gpu::Buffer(ctx, tooLarge, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal),
                       doctest::Contains("a buffer needs"), gpu::LimitError);
  if (ctx.info().maxBufferSize > 0 && ctx.info().maxBufferSize < UINT64_MAX) {
    CHECK_THROWS_WITH_AS(gpu::Buffer(ctx, ctx.info().maxBufferSize + 1, gpu::kStorageUsage,
                                     gpu::MemoryUse::DeviceLocal),
                         doctest::Contains("maxBufferSize"), gpu::LimitError);
  }
  CHECK(ctx.validationMessageCount() == 0);
}
