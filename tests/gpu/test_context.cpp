#include <doctest/doctest.h>

#include <numeric>

#include "core/error.h"
#include "gpu/buffer.h"
#include "gpu/commands.h"
#include "gpu/program.h"
#include "gpu/timestamps.h"
#include "gpu_fixture.h"
#include "shaders/synth_bindings.h"

using namespace throng;

TEST_CASE("context: a device with a compute+graphics queue, validation on") {
  gpu::Context& ctx = test::gpuContext();
  CHECK(ctx.device() != VK_NULL_HANDLE);
  CHECK(ctx.validationEnabled());
  CHECK(!ctx.info().name.empty());
  MESSAGE("device: ", ctx.info().name, " driver: ", ctx.info().driver);
  CHECK(!gpu::listDevices().empty());
}

TEST_CASE("context: an unknown device name is a clear error") {
  gpu::ContextOptions options;
  options.device = "no-such-gpu-xyz";
  options.quiet = true;
  CHECK_THROWS_WITH_AS(gpu::Context{options}, doctest::Contains("no Vulkan device matches"), Error);
}

namespace {
// A small upload, dispatch-free round trip that touches device, queue and command functions.
void checkRoundTrip(gpu::Context& ctx) {
  std::vector<uint32_t> data(256);
  std::iota(data.begin(), data.end(), 11u);
  gpu::Buffer buffer = gpu::makeStorageBuffer<uint32_t>(ctx, data);
  CHECK(gpu::readback<uint32_t>(ctx, buffer, data.size()) == data);
}

gpu::ContextOptions ownContextOptions(bool validation) {
  gpu::ContextOptions options;
  options.validation = validation;
  options.quiet = true;
  return options;
}
}  // namespace

// listDevices() makes a temporary instance without the debug-utils extension; loading volk's
// global pointers from it left vkDestroyDebugUtilsMessengerEXT null for every live context.
TEST_CASE("context: listDevices leaves a live context's entry points intact") {
  {
    gpu::Context ctx(ownContextOptions(true));
    REQUIRE(ctx.validationEnabled());
    const PFN_vkDestroyDebugUtilsMessengerEXT before = vkDestroyDebugUtilsMessengerEXT;
    REQUIRE((before != nullptr));
    CHECK(!gpu::listDevices().empty());
    CHECK((vkDestroyDebugUtilsMessengerEXT == before));
    checkRoundTrip(ctx);
    CHECK(ctx.validationMessageCount() == 0);
  }  // ~Context destroys its debug messenger here
  checkRoundTrip(test::gpuContext());
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

TEST_CASE("context: contexts made and destroyed beside the shared one leave it working") {
  {
    gpu::Context withoutValidation(ownContextOptions(false));
    checkRoundTrip(withoutValidation);
  }
  gpu::ContextOptions unknown = ownContextOptions(true);
  unknown.device = "no-such-gpu-xyz";
  CHECK_THROWS_AS(gpu::Context{unknown}, Error);  // fails after its instance exists
  checkRoundTrip(test::gpuContext());
  CHECK(test::gpuContext().validationMessageCount() == 0);
}

TEST_CASE("buffer: device-local round trip through staging") {
  gpu::Context& ctx = test::gpuContext();
  std::vector<uint32_t> data(10000);
  std::iota(data.begin(), data.end(), 7u);
  gpu::Buffer buffer = gpu::makeStorageBuffer<uint32_t>(ctx, data);
  CHECK(gpu::readback<uint32_t>(ctx, buffer, data.size()) == data);
  CHECK(gpu::readback<uint32_t>(ctx, buffer, 3, 100) == std::vector<uint32_t>{107, 108, 109});
  CHECK_THROWS_AS(gpu::readback<uint32_t>(ctx, buffer, 10, 9995), Error);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("program: reflection and a checked dispatch") {
  gpu::Context& ctx = test::gpuContext();
  gpu::ComputeProgram program(ctx, "test_scale.comp");
  CHECK(program.localSizeX() == 64);
  REQUIRE(program.reflection().bindings.size() == 2);
  CHECK(program.reflection().bindings[0].type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
  CHECK(program.reflection().pushConstantSize == 8);

  const uint32_t n = 1000;
  std::vector<float> input(n);
  for (uint32_t i = 0; i < n; ++i) input[i] = 0.5f * i;
  gpu::Buffer in = gpu::makeStorageBuffer<float>(ctx, input);
  gpu::Buffer out(ctx, n * sizeof(float), gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  struct Push {
    float scale;
    uint32_t count;
  } push{3.0f, n};
  gpu::TimestampPool timestamps(ctx, 2);
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    timestamps.write(cmd);
    gpu::Binding bindings[] = {gpu::storageBinding(gpu_types::kTestScaleBindingInput, in),
                               gpu::storageBinding(gpu_types::kTestScaleBindingOutput, out)};
    gpu::dispatch(cmd, program, bindings, push, n);
    timestamps.write(cmd);
  });
  std::vector<float> result = gpu::readback<float>(ctx, out, n);
  for (uint32_t i = 0; i < n; ++i) REQUIRE(result[i] == doctest::Approx(input[i] * 3.0f + i));
  double ms = timestamps.millisecondsBetween(timestamps.fetch(), 0, 1);
  CHECK(ms >= 0.0);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("program: a uniform texel buffer is reflected, bound and read") {
  gpu::Context& ctx = test::gpuContext();
  gpu::ComputeProgram program(ctx, "test_texels.comp");
  REQUIRE(program.reflection().bindings.size() == 2);
  CHECK(program.reflection().bindings[0].type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
  CHECK(program.reflection().bindings[1].type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);

  const uint32_t n = 300;
  std::vector<float> texels(4 * n);
  for (uint32_t i = 0; i < 4 * n; ++i) texels[i] = float(i % 7) + 0.25f * float(i / 4);
  gpu::Buffer source = gpu::makeStorageBuffer<float>(ctx, texels, gpu::MemoryUse::DeviceLocal,
                                                     VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT);
  gpu::Handle<VkBufferView> view = gpu::makeBufferView(ctx, source, VK_FORMAT_R32G32B32A32_SFLOAT);
  gpu::Buffer out(ctx, n * sizeof(float), gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  const uint32_t count = n;
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    gpu::Binding bindings[] = {gpu::uniformTexelBinding(gpu_types::kTestTexelsBindingTexels, view),
                               gpu::storageBinding(gpu_types::kTestTexelsBindingOutput, out)};
    gpu::dispatch(cmd, program, bindings, count, n);
  });
  std::vector<float> result = gpu::readback<float>(ctx, out, n);
  for (uint32_t i = 0; i < n; ++i) {
    const float* t = &texels[4 * i];
    REQUIRE(result[i] == doctest::Approx(t[0] + 10.0f * t[1] + 100.0f * t[2] + 1000.0f * t[3]));
  }
  // A storage binding where the shader declares texels, and a null view, are reported.
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    gpu::Binding wrongType[] = {gpu::storageBinding(gpu_types::kTestTexelsBindingTexels, source),
                                gpu::storageBinding(gpu_types::kTestTexelsBindingOutput, out)};
    CHECK_THROWS_WITH_AS(gpu::dispatch(cmd, program, wrongType, count, n),
                         doctest::Contains("expects descriptor type"), Error);
    gpu::Binding nullView[] = {
        gpu::uniformTexelBinding(gpu_types::kTestTexelsBindingTexels, VK_NULL_HANDLE),
        gpu::storageBinding(gpu_types::kTestTexelsBindingOutput, out)};
    CHECK_THROWS_WITH_AS(gpu::dispatch(cmd, program, nullView, count, n),
                         doctest::Contains("null buffer view"), Error);
  });
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("program: missing binding and wrong push size are reported") {
  gpu::Context& ctx = test::gpuContext();
  gpu::ComputeProgram program(ctx, "test_scale.comp");
  gpu::Buffer in(ctx, 64, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  uint32_t wrongPush = 1;
  gpu::Binding one[] = {gpu::storageBinding(gpu_types::kTestScaleBindingInput, in)};
  struct Push {
    float scale;
    uint32_t count;
  } push{1.0f, 4};
  gpu::CommandPool pool(ctx);
  VkCommandBuffer cmd = pool.allocate();
  gpu::beginCommands(cmd);
  CHECK_THROWS_WITH_AS(gpu::dispatch(cmd, program, one, push, 4),
                       doctest::Contains("binding 1 was not provided"), Error);
  CHECK_THROWS_WITH_AS(gpu::dispatch(cmd, program, one, wrongPush, 4),
                       doctest::Contains("push constants of 4 bytes"), Error);
  CHECK_THROWS_WITH_AS(gpu::ComputeProgram(ctx, "nope.comp"), doctest::Contains("not embedded"),
                       Error);
  gpu::endCommands(cmd);
  CHECK(ctx.validationMessageCount() == 0);
}
