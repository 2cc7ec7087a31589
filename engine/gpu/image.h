#pragma once
// 2D images with one view (motion textures, render targets), samplers, and layout changes.
#include <span>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/handle.h"

namespace throng::gpu {

// Where an image's texels live: device memory in the driver's own layout, or host-visible
// memory in rows the host reads in place (linear tiling, mapped while the image lives).
enum class ImageMemory { Device, HostMapped };

class Image2D {
 public:
  Image2D() = default;
  Image2D(const Context& context, uint32_t width, uint32_t height, VkFormat format,
          VkImageUsageFlags usage, VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT,
          ImageMemory memory = ImageMemory::Device);

  // Whether the device makes host-mapped images of `format` with `usage` at width × height
  // (linear tiling is optional for most uses, attachments above all).
  static bool hostMappable(const Context& context, VkFormat format, VkImageUsageFlags usage,
                           uint32_t width, uint32_t height);

  VkImage get() const { return image_; }
  VkImageView view() const { return view_; }
  VkFormat format() const { return format_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  VkImageAspectFlags aspect() const { return aspect_; }
  explicit operator bool() const { return static_cast<bool>(image_); }
  // A host-mapped image's first texel and the bytes from one row to the next (null and 0 for a
  // device image). The host reads them in VK_IMAGE_LAYOUT_GENERAL, after the device's writes.
  const uint8_t* mapped() const { return static_cast<const uint8_t*>(mapped_); }
  VkDeviceSize rowPitch() const { return rowPitch_; }
  // A host-mapped image's texels as a buffer of `usage` (rowPitch() bytes a row, from texel
  // (0, 0)), for a pass that writes the image's rows without a copy: the image is then in
  // VK_IMAGE_LAYOUT_GENERAL. Empty for a device image or where the device binds no such buffer
  // to the image's memory. The image outlives the buffer.
  Buffer texelBuffer(const Context& context, VkBufferUsageFlags usage) const;

 private:
  Handle<VkDeviceMemory> memory_;
  Handle<VkImage> image_;
  Handle<VkImageView> view_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  uint32_t width_ = 0, height_ = 0;
  VkImageAspectFlags aspect_ = VK_IMAGE_ASPECT_COLOR_BIT;
  void* mapped_ = nullptr;  // unmapped when memory_ is freed
  VkDeviceSize rowPitch_ = 0;
  VkDeviceSize texelOffset_ = 0;  // texel (0, 0) in memory_, host-mapped
  uint32_t memoryType_ = 0;
  VkDeviceSize memorySize_ = 0;
};

void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect,
                     VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                     VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                     VkAccessFlags dstAccess);

// Uploads tightly packed texels and leaves the image in SHADER_READ_ONLY_OPTIMAL.
void uploadImage(const Context& context, const Image2D& image, std::span<const uint8_t> texels);

Handle<VkSampler> makeNearestSampler(const Context& context);

}  // namespace throng::gpu
