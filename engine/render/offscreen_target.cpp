#include "render/offscreen_target.h"

#include <cstring>
#include <utility>

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

namespace {

constexpr VkImageUsageFlags kColorUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                          VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                          VK_IMAGE_USAGE_TRANSFER_DST_BIT;

bool readsInPlace(const gpu::Context& context, uint32_t width, uint32_t height, Readback readback) {
  if (readback == Readback::Copy) return false;
  const bool mappable =
      gpu::Image2D::hostMappable(context, kColorFormat, kColorUsage, width, height);
  if (readback == Readback::InPlace && !mappable)
    fail("a ", width, "x", height, " render target read in place: the device maps no such image");
  return readback == Readback::InPlace || (mappable && context.info().isCpu());
}

void checkSlot(const OffscreenTarget& target, uint32_t slot) {
  const size_t slots = target.inPlace() ? target.colors.size() : target.readbacks.size();
  if (slot >= slots) fail("readback slot ", slot, " of an offscreen target with ", slots);
}

// Every slot's texels as a storage buffer, or none: the renderer treats all slots alike.
void addColorTexels(const gpu::Context& context, OffscreenTarget& t) {
  for (const gpu::Image2D& color : t.colors) {
    gpu::Buffer texels;
    if (color.rowPitch() == VkDeviceSize(t.width) * 4)
      texels = color.texelBuffer(context, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    if (!texels) {
      t.colorTexels.clear();
      return;
    }
    t.colorTexels.push_back(std::move(texels));
  }
}

}  // namespace

const gpu::Image2D& OffscreenTarget::color(uint32_t slot) const {
  checkSlot(*this, slot);
  return colors[inPlace() ? slot : 0];
}

OffscreenTarget makeOffscreenTarget(const gpu::Context& context, uint32_t width, uint32_t height,
                                    uint32_t readbackSlots, Readback readback) {
  if (width == 0 || height == 0 || width > 16384 || height > 16384)
    fail("image size ", width, "x", height, " is outside 1..16384 pixels per side");
  if (readbackSlots < 1 || readbackSlots > 2)
    fail("an offscreen target's readback slots: expected 1..2, got ", readbackSlots);
  checkTargetSize(context, width, height, concat("a ", width, "x", height, " render target"));
  OffscreenTarget t;
  t.width = width;
  t.height = height;
  if (readsInPlace(context, width, height, readback)) {
    for (uint32_t slot = 0; slot < readbackSlots; ++slot)
      t.colors.emplace_back(context, width, height, kColorFormat, kColorUsage,
                            VK_IMAGE_ASPECT_COLOR_BIT, gpu::ImageMemory::HostMapped);
    addColorTexels(context, t);
  } else {
    t.colors.emplace_back(context, width, height, kColorFormat, kColorUsage);
    for (uint32_t slot = 0; slot < readbackSlots; ++slot)
      t.readbacks.emplace_back(context, VkDeviceSize(width) * height * 4,
                               VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUse::HostVisible);
  }
  t.depth =
      gpu::Image2D(context, width, height, kDepthFormat,
                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                   VK_IMAGE_ASPECT_DEPTH_BIT);
  return t;
}

VkImageLayout readbackLayout(const OffscreenTarget& target) {
  return target.inPlace() ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
}

void recordReadback(VkCommandBuffer cmd, const OffscreenTarget& target, uint32_t slot) {
  checkSlot(target, slot);
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  if (target.inPlace()) {  // whatever wrote the image last, and its layout's change
    barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                         &barrier, 0, nullptr, 0, nullptr);
    return;
  }
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {target.width, target.height, 1};
  vkCmdCopyImageToBuffer(cmd, target.color().get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         target.readbacks[slot].get(), 1, &region);
  barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &barrier, 0, nullptr, 0, nullptr);
}

void readbackInto(const OffscreenTarget& target, ImageRgba8& image, uint32_t slot) {
  checkSlot(target, slot);
  image.width = static_cast<int>(target.width);
  image.height = static_cast<int>(target.height);
  image.pixels.resize(size_t(target.width) * target.height);  // a recycled frame keeps its memory
  // The slot's buffer holds whole rows; a mapped image's rows may lie further apart.
  const size_t rowBytes = size_t(target.width) * sizeof(Rgba8);
  const uint8_t* rows = target.inPlace()
                            ? target.colors[slot].mapped()
                            : static_cast<const uint8_t*>(target.readbacks[slot].mapped());
  const size_t pitch = target.inPlace() ? size_t(target.colors[slot].rowPitch()) : rowBytes;
  for (uint32_t y = 0; y < target.height; ++y)
    std::memcpy(&image.pixels[size_t(y) * target.width], rows + y * pitch, rowBytes);
}

ImageRgba8 readbackImage(const OffscreenTarget& target, uint32_t slot) {
  ImageRgba8 image;
  readbackInto(target, image, slot);
  return image;
}

FrameTargets offscreenFrameTargets(const OffscreenTarget& target, uint32_t slot) {
  const gpu::Image2D& color = target.color(slot);
  FrameTargets frame{color.get(),  color.view(),  target.depth.get(),     target.depth.view(),
                     target.width, target.height, readbackLayout(target), true};
  if (!target.colorTexels.empty()) frame.colorTexels = &target.colorTexels[slot];
  return frame;
}

}  // namespace throng::render
