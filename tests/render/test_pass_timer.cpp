// The renderer's per-pass GPU times (THRONG_RENDER_PASS_TIMES=1): a frame whose recording failed
// was never submitted, so its marks are never written; destroying the timer then must neither
// wait for them nor throw (it runs while the failure unwinds).
#include <doctest/doctest.h>

#include <cstdlib>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu_fixture.h"
#include "render/pass_timer.h"

using namespace throng;

namespace {
// A timer made with the variable set, which is read once, at construction.
std::unique_ptr<render::PassTimer> enabledTimer(const gpu::Context& ctx) {
  setenv("THRONG_RENDER_PASS_TIMES", "1", 1);
  auto timer = std::make_unique<render::PassTimer>(ctx);
  unsetenv("THRONG_RENDER_PASS_TIMES");
  return timer;
}
}  // namespace

TEST_CASE(
    "pass timer: completed frames are timed, a frame that failed while recording is dropped") {
  gpu::Context& ctx = test::gpuContext();
  std::unique_ptr<render::PassTimer> timer = enabledTimer(ctx);
  REQUIRE(timer->enabled());
  for (int frame = 0; frame < 2; ++frame)
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      timer->beginFrame(cmd);
      timer->mark(cmd, "empty");
    });
  CHECK_THROWS_AS(gpu::submitAndWait(ctx,
                                     [&](VkCommandBuffer cmd) {
                                       timer->beginFrame(cmd);  // reads the frames before
                                       timer->mark(cmd, "empty");
                                       fail("recording failed");
                                     }),
                  Error);
  CHECK_NOTHROW(timer.reset());
  CHECK(ctx.validationMessageCount() == 0);
}
