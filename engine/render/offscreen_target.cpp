#include "render/offscreen_target.h"

#include <cstring>

#include "core/error.h"
#include "gpu/limits.h"

namespace throng::render {

void checkTargetSize(const gpu::Context& context, uint32_t width, uint32_t height,
                     const std::string& what) {
  gpu::checkImageSize(context, what, width, height, /*attachment=*/true);
  if (!context.info().int64Atomics) return;  // no joint splat, no visibility buffer
  const uint64_t visibilityBytes = uint64_t(width) * height * sizeof(uint64_t);
  gpu::checkLimit(context, concat(what, "'s joint-splat visibility buffer (8 bytes a pixel)"),
                  "maxStorageBufferRange", visibilityBytes, context.info().maxStorageBufferRange);
}

OffscreenTarget makeOffscreenTarget(const gpu::Context& context, uint32_t width, uint32_t height,
                                    uint32_t readbackSlots) {
  if (width == 0 || height == 0 || width > 16384 || height > 16384)
    fail("image size ", width, "x", height, " is outside 1..16384 pixels per side");
  if (readbackSlots < 1 || readbackSlots > 2)
    fail("an offscreen target's readback slots: expected 1..2, got ", readbackSlots);
  checkTargetSize(context, width, height, concat("a ", width, "x", height, " render target"));
  OffscreenTarget t;
  t.width = width;
  t.height = height;
  t.color = gpu::Image2D(context, width, height, kColorFormat,
                         VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                             VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  t.depth =
      gpu::Image2D(context, width, height, kDepthFormat,
                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                   VK_IMAGE_ASPECT_DEPTH_BIT);
  for (uint32_t slot = 0; slot < readbackSlots; ++slot)
    t.readbacks.emplace_back(context, VkDeviceSize(width) * height * 4,
                             VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::HostVisible);
  return t;
}

namespace {

// The readback slot `slot` of `target`, or Error naming the slots there are.
const gpu::Buffer& readbackSlot(const OffscreenTarget& target, uint32_t slot) {
  if (slot >= target.readbacks.size())
    fail("readback slot ", slot, " of an offscreen target with ", target.readbacks.size());
  return target.readbacks[slot];
}

}  // namespace

void recordReadback(VkCommandBuffer cmd, const OffscreenTarget& target, uint32_t slot) {
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {target.width, target.height, 1};
  vkCmdCopyImageToBuffer(cmd, target.color.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         readbackSlot(target, slot).get(), 1, &region);
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &barrier, 0, nullptr, 0, nullptr);
}

void readbackInto(const OffscreenTarget& target, ImageRgba8& image, uint32_t slot) {
  const gpu::Buffer& readback = readbackSlot(target, slot);
  image.width = static_cast<int>(target.width);
  image.height = static_cast<int>(target.height);
  image.pixels.resize(size_t(target.width) * target.height);  // a recycled frame keeps its memory
  std::memcpy(image.pixels.data(), readback.mapped(), image.pixels.size() * sizeof(Rgba8));
}

ImageRgba8 readbackImage(const OffscreenTarget& target, uint32_t slot) {
  ImageRgba8 image;
  readbackInto(target, image, slot);
  return image;
}

FrameTargets offscreenFrameTargets(const OffscreenTarget& target) {
  return {target.color.get(),
          target.color.view(),
          target.depth.get(),
          target.depth.view(),
          target.width,
          target.height,
          VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
          true};
}

}  // namespace throng::render
