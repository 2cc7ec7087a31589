// Synchronization validation is on with the validation layer: a missing barrier is reported.
// Its own context, so that the deliberate hazard does not count against the shared one.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "gpu/buffer.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"

using namespace throng;

namespace {
bool anyIdStartsWith(const std::vector<std::string>& ids, const std::string& prefix) {
  return std::any_of(ids.begin(), ids.end(),
                     [&](const std::string& id) { return id.rfind(prefix, 0) == 0; });
}
}  // namespace

TEST_CASE(
    "sync validation: two transfer writes without a barrier are a SYNC-HAZARD-WRITE-AFTER-WRITE") {
  const char* off = std::getenv("THRONG_SYNC_VALIDATION");
  if (off && std::strcmp(off, "0") == 0) {
    MESSAGE("THRONG_SYNC_VALIDATION=0: synchronization validation is off by request");
    return;
  }
  gpu::ContextOptions options;
  options.validation = true;
  options.quiet = true;
  gpu::Context ctx(options);
  REQUIRE(ctx.syncValidationEnabled());
  gpu::Buffer buffer(ctx, 4096, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);

  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {  // ordered by a barrier: no message
    vkCmdFillBuffer(cmd, buffer.get(), 0, 4096, 1u);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    vkCmdFillBuffer(cmd, buffer.get(), 0, 4096, 2u);
  });
  CHECK(ctx.validationMessageCount() == 0);

  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, buffer.get(), 0, 4096, 3u);
    vkCmdFillBuffer(cmd, buffer.get(), 0, 4096, 4u);  // no barrier between the two writes
  });
  CHECK(ctx.validationMessageCount() >= 1);
  CHECK(anyIdStartsWith(ctx.validationMessageIds(), "SYNC-HAZARD-WRITE-AFTER-WRITE"));
}

TEST_CASE("sync validation: the shared test context has it on") {
  const char* off = std::getenv("THRONG_SYNC_VALIDATION");
  if (off && std::strcmp(off, "0") == 0) return;
  CHECK(test::gpuContext().syncValidationEnabled());
}
