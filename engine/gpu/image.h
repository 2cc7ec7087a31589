#pragma once
// 2D images with one view (motion textures, render targets), samplers, and layout changes.
#include <span>

#include "gpu/context.h"
#include "gpu/handle.h"

namespace throng::gpu {

class Image2D {
 public:
  Image2D() = default;
  Image2D(const Context& context, uint32_t width, uint32_t height, VkFormat format,
          VkImageUsageFlags usage, VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT);

  VkImage get() const { return image_; }
  VkImageView view() const { return view_; }
  VkFormat format() const { return format_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }
  VkImageAspectFlags aspect() const { return aspect_; }
  explicit operator bool() const { return static_cast<bool>(image_); }

 private:
  Handle<VkDeviceMemory> memory_;
  Handle<VkImage> image_;
  Handle<VkImageView> view_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  uint32_t width_ = 0, height_ = 0;
  VkImageAspectFlags aspect_ = VK_IMAGE_ASPECT_COLOR_BIT;
};

void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect,
                     VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                     VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

// Uploads tightly packed texels and leaves the image in SHADER_READ_ONLY_OPTIMAL.
void uploadImage(const Context& context, const Image2D& image, std::span<const uint8_t> texels);

Handle<VkSampler> makeNearestSampler(const Context& context);

}  // namespace throng::gpu
