// The offscreen target's readback slots: a frame loop reads one frame's pixels out of one slot
// while the next frame is copied into the other, so each slot must keep the copy made into it.
#include <doctest/doctest.h>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/image.h"
#include "gpu_fixture.h"
#include "render/offscreen_target.h"

using namespace throng;

namespace {

// Clears the target's colour image to `colour` and copies it into readback slot `slot`.
void recordClearAndReadback(VkCommandBuffer cmd, const render::OffscreenTarget& target,
                            const VkClearColorValue& colour, uint32_t slot, bool first) {
  gpu::transitionImage(cmd, target.color.get(), VK_IMAGE_ASPECT_COLOR_BIT,
                       first ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       first ? 0 : VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_TRANSFER_WRITE_BIT);
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, target.color.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &colour, 1,
                       &range);
  gpu::transitionImage(cmd, target.color.get(), VK_IMAGE_ASPECT_COLOR_BIT,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
  render::recordReadback(cmd, target, slot);
}

bool allPixels(const ImageRgba8& image, Rgba8 colour) {
  for (const Rgba8& p : image.pixels)
    if (!(p == colour)) return false;
  return !image.pixels.empty();
}

}  // namespace

TEST_CASE("offscreen target: readback slots are checked") {
  gpu::Context& ctx = test::gpuContext();
  CHECK_THROWS_AS(render::makeOffscreenTarget(ctx, 8, 8, 0), Error);
  CHECK_THROWS_AS(render::makeOffscreenTarget(ctx, 8, 8, 3), Error);
  const render::OffscreenTarget one = render::makeOffscreenTarget(ctx, 8, 8);
  CHECK(one.readbacks.size() == 1);
  ImageRgba8 image;
  CHECK_THROWS_AS(render::readbackInto(one, image, 1), Error);
}

TEST_CASE("offscreen target: each readback slot keeps the copy made into it") {
  gpu::Context& ctx = test::gpuContext();
  const render::OffscreenTarget target = render::makeOffscreenTarget(ctx, 40, 24, 2);
  REQUIRE(target.readbacks.size() == 2);
  const VkClearColorValue red{{1.0f, 0.0f, 0.0f, 1.0f}}, blue{{0.0f, 0.0f, 1.0f, 1.0f}};
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    recordClearAndReadback(cmd, target, red, 0, true);
    recordClearAndReadback(cmd, target, blue, 1, false);
  });
  CHECK(allPixels(render::readbackImage(target, 0), Rgba8{255, 0, 0, 255}));
  CHECK(allPixels(render::readbackImage(target, 1), Rgba8{0, 0, 255, 255}));
  // The next frame into slot 0 leaves slot 1 as it was.
  const VkClearColorValue green{{0.0f, 1.0f, 0.0f, 1.0f}};
  gpu::submitAndWait(
      ctx, [&](VkCommandBuffer cmd) { recordClearAndReadback(cmd, target, green, 0, false); });
  CHECK(allPixels(render::readbackImage(target, 0), Rgba8{0, 255, 0, 255}));
  CHECK(allPixels(render::readbackImage(target, 1), Rgba8{0, 0, 255, 255}));
  CHECK(ctx.validationMessageCount() == 0);
}
