// The offscreen target's readback slots, copied or read in place: a frame loop reads one frame's
// pixels out of one slot while the next frame goes to the other, so each slot must keep what was
// drawn for it.
#include <doctest/doctest.h>

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/image.h"
#include "gpu_fixture.h"
#include "render/offscreen_target.h"

using namespace throng;

namespace {

// Clears slot `slot`'s colour image to `colour` and makes it the host's: the layout it is left
// in (`from`: UNDEFINED the first time) is the target's readback layout.
void recordClearAndReadback(VkCommandBuffer cmd, const render::OffscreenTarget& target,
                            const VkClearColorValue& colour, uint32_t slot, VkImageLayout from) {
  const VkImage image = target.color(slot).get();
  gpu::transitionImage(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, from,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_TRANSFER_WRITE_BIT);
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &colour, 1, &range);
  gpu::transitionImage(cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                       render::readbackLayout(target), VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_TRANSFER_READ_BIT);
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
  for (const render::Readback readback : {render::Readback::Copy, render::Readback::Auto}) {
    const render::OffscreenTarget one = render::makeOffscreenTarget(ctx, 8, 8, 1, readback);
    CHECK(one.colors.size() == 1);
    ImageRgba8 image;
    CHECK_THROWS_AS(render::readbackInto(one, image, 1), Error);
    CHECK_THROWS_AS(one.color(1), Error);
  }
}

TEST_CASE("offscreen target: a CPU device reads the frame in place, a GPU copies it") {
  gpu::Context& ctx = test::gpuContext();
  const render::OffscreenTarget automatic = render::makeOffscreenTarget(ctx, 40, 24, 2);
  CHECK(automatic.inPlace() == ctx.info().isCpu());
  CHECK(render::readbackLayout(automatic) ==
        (ctx.info().isCpu() ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL));
  const render::OffscreenTarget copied =
      render::makeOffscreenTarget(ctx, 40, 24, 2, render::Readback::Copy);
  CHECK(!copied.inPlace());
  CHECK(copied.colors.size() == 1);
  CHECK(copied.readbacks.size() == 2);
  CHECK(&copied.color(0) == &copied.color(1));  // one image, copied into either slot
  if (!automatic.inPlace()) return;
  CHECK(automatic.colors.size() == 2);
  CHECK(automatic.readbacks.empty());
  CHECK(automatic.color(0).rowPitch() >= 40 * 4);
  CHECK(render::offscreenFrameTargets(automatic, 1).color == automatic.color(1).get());
  CHECK(render::offscreenFrameTargets(copied, 1).colorTexels == nullptr);
  // Rows 40 × 4 bytes apart: each slot's texels as a buffer, the resolve's to write in place.
  if (automatic.color(0).rowPitch() != 40 * 4) return;
  REQUIRE(automatic.colorTexels.size() == 2);
  CHECK(automatic.colorTexels[1].size() == 40 * 24 * 4);
  CHECK(render::offscreenFrameTargets(automatic, 1).colorTexels == &automatic.colorTexels[1]);
}

TEST_CASE("offscreen target: a host-mapped image's texel buffer is the image's memory") {
  gpu::Context& ctx = test::gpuContext();
  const VkImageUsageFlags usage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  const gpu::Image2D device(ctx, 16, 4, render::kColorFormat, usage);
  CHECK(!device.texelBuffer(ctx, VK_BUFFER_USAGE_TRANSFER_DST_BIT));
  if (!gpu::Image2D::hostMappable(ctx, render::kColorFormat, usage, 16, 4)) return;
  const gpu::Image2D image(ctx, 16, 4, render::kColorFormat, usage, VK_IMAGE_ASPECT_COLOR_BIT,
                           gpu::ImageMemory::HostMapped);
  const gpu::Buffer texels = image.texelBuffer(ctx, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  // A CPU device's (lavapipe's) image memory takes such a buffer: its renders write in place.
  if (ctx.info().isCpu()) REQUIRE(texels);
  if (!texels) return;  // the renderer copies its planes in instead
  CHECK(texels.size() == image.rowPitch() * 4);
  gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    gpu::transitionImage(cmd, image.get(), VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdFillBuffer(cmd, texels.get(), 0, VK_WHOLE_SIZE, 0x11223344u);
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
  });
  const uint8_t* row = image.mapped() + 3 * image.rowPitch();  // the last row's last texel
  CHECK(row[15 * 4] == 0x44);
  CHECK(row[15 * 4 + 3] == 0x11);
  CHECK(ctx.validationMessageCount() == 0);
}

TEST_CASE("offscreen target: each readback slot keeps what was drawn for it") {
  gpu::Context& ctx = test::gpuContext();
  for (const render::Readback readback : {render::Readback::Copy, render::Readback::Auto}) {
    // An odd width: rows of a mapped image may lie further apart than a row's bytes.
    const render::OffscreenTarget target = render::makeOffscreenTarget(ctx, 41, 23, 2, readback);
    CAPTURE(target.inPlace());
    REQUIRE(target.color(1).get() != VK_NULL_HANDLE);
    const VkClearColorValue red{{1.0f, 0.0f, 0.0f, 1.0f}}, blue{{0.0f, 0.0f, 1.0f, 1.0f}};
    const VkImageLayout after = render::readbackLayout(target);
    gpu::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      recordClearAndReadback(cmd, target, red, 0, VK_IMAGE_LAYOUT_UNDEFINED);
      recordClearAndReadback(cmd, target, blue, 1,
                             target.inPlace() ? VK_IMAGE_LAYOUT_UNDEFINED : after);
    });
    CHECK(allPixels(render::readbackImage(target, 0), Rgba8{255, 0, 0, 255}));
    CHECK(allPixels(render::readbackImage(target, 1), Rgba8{0, 0, 255, 255}));
    // The next frame into slot 0 leaves slot 1 as it was.
    const VkClearColorValue green{{0.0f, 1.0f, 0.0f, 1.0f}};
    gpu::submitAndWait(
        ctx, [&](VkCommandBuffer cmd) { recordClearAndReadback(cmd, target, green, 0, after); });
    CHECK(allPixels(render::readbackImage(target, 0), Rgba8{0, 255, 0, 255}));
    CHECK(allPixels(render::readbackImage(target, 1), Rgba8{0, 0, 255, 255}));
  }
  CHECK(ctx.validationMessageCount() == 0);
}
