#pragma once
// The window's swapchain: format, present mode and size choice, the images with their views,
// and one "rendered" semaphore per image (present waits on it). Recreated, not resized.
#include <span>
#include <vector>

#include "gpu/context.h"
#include "gpu/handle.h"

namespace throng::render {

// A UNORM 8-bit format first: the shaders write display values, as into the headless target.
VkSurfaceFormatKHR chooseSurfaceFormat(std::span<const VkSurfaceFormatKHR> available);
// vsync: FIFO (always supported). Without: MAILBOX, else IMMEDIATE, else FIFO.
VkPresentModeKHR choosePresentMode(std::span<const VkPresentModeKHR> available, bool vsync);
// The surface's current extent when it dictates one, else the framebuffer clamped to the limits.
VkExtent2D chooseExtent(const VkSurfaceCapabilitiesKHR& capabilities, VkExtent2D framebuffer);
uint32_t chooseImageCount(const VkSurfaceCapabilitiesKHR& capabilities);
const char* presentModeName(VkPresentModeKHR mode);
// Channel order of 8-bit formats a screenshot can read back; false for anything else.
bool isReadableFormat(VkFormat format, bool* bgra = nullptr);

class Swapchain {
 public:
  // `previous` (may be null) is handed to the driver as oldSwapchain so it can reuse resources.
  Swapchain(const gpu::Context& context, VkSurfaceKHR surface, VkExtent2D framebuffer, bool vsync,
            const Swapchain* previous = nullptr);

  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  VkPresentModeKHR presentMode() const { return presentMode_; }
  bool vsync() const { return vsync_; }
  bool canReadBack() const { return canReadBack_; }
  uint32_t imageCount() const { return static_cast<uint32_t>(images_.size()); }
  uint32_t minImageCount() const { return minImageCount_; }
  VkImage image(uint32_t i) const { return images_[i]; }
  VkImageView view(uint32_t i) const { return views_[i]; }

  // False when the swapchain no longer matches the surface (recreate it); true with `index`.
  // Signals `acquired` when the image may be written.
  bool acquire(VkSemaphore acquired, uint32_t& index) const;
  // The submission that draws image `i` signals this; present() waits on it.
  VkSemaphore renderedSemaphore(uint32_t i) const { return rendered_[i]; }
  // False when out of date (recreate before the next frame).
  bool present(uint32_t index) const;

 private:
  const gpu::Context* context_ = nullptr;
  gpu::Handle<VkSwapchainKHR> swapchain_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
  bool vsync_ = true;
  bool canReadBack_ = false;
  uint32_t minImageCount_ = 2;
  std::vector<VkImage> images_;
  std::vector<gpu::Handle<VkImageView>> views_;
  std::vector<gpu::Handle<VkSemaphore>> rendered_;
};

gpu::Handle<VkSemaphore> makeSemaphore(const gpu::Context& context);

}  // namespace throng::render
