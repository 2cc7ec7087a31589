#include "viewer/swapchain.h"

#include <algorithm>

#include "core/error.h"
#include "gpu/vk_check.h"

namespace throng::render {

VkSurfaceFormatKHR chooseSurfaceFormat(std::span<const VkSurfaceFormatKHR> available) {
  if (available.empty()) fail("the window surface reports no formats");
  // A single UNDEFINED entry means "anything you like" (old drivers).
  if (available.size() == 1 && available[0].format == VK_FORMAT_UNDEFINED)
    return {VK_FORMAT_B8G8R8A8_UNORM, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR};
  for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM}) {
    for (const VkSurfaceFormatKHR& f : available)
      if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
  }
  return available[0];
}

VkPresentModeKHR choosePresentMode(std::span<const VkPresentModeKHR> available, bool vsync) {
  if (vsync) return VK_PRESENT_MODE_FIFO_KHR;
  for (VkPresentModeKHR wanted : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR}) {
    if (std::find(available.begin(), available.end(), wanted) != available.end()) return wanted;
  }
  return VK_PRESENT_MODE_FIFO_KHR;
}

VkExtent2D chooseExtent(const VkSurfaceCapabilitiesKHR& caps, VkExtent2D framebuffer) {
  if (caps.currentExtent.width != UINT32_MAX) return caps.currentExtent;
  return {std::clamp(framebuffer.width, caps.minImageExtent.width, caps.maxImageExtent.width),
          std::clamp(framebuffer.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
}

uint32_t chooseImageCount(const VkSurfaceCapabilitiesKHR& caps) {
  // One more than the minimum so acquiring never waits for the presentation engine to let go.
  uint32_t count = std::max(caps.minImageCount + 1, 2u);
  if (caps.maxImageCount != 0) count = std::min(count, caps.maxImageCount);
  return count;
}

const char* presentModeName(VkPresentModeKHR mode) {
  switch (mode) {
    case VK_PRESENT_MODE_FIFO_KHR:
      return "fifo (vsync)";
    case VK_PRESENT_MODE_FIFO_RELAXED_KHR:
      return "fifo relaxed";
    case VK_PRESENT_MODE_MAILBOX_KHR:
      return "mailbox";
    case VK_PRESENT_MODE_IMMEDIATE_KHR:
      return "immediate";
    default:
      return "other";
  }
}

bool isReadableFormat(VkFormat format, bool* bgra) {
  bool isBgra = format == VK_FORMAT_B8G8R8A8_UNORM || format == VK_FORMAT_B8G8R8A8_SRGB;
  bool isRgba = format == VK_FORMAT_R8G8B8A8_UNORM || format == VK_FORMAT_R8G8B8A8_SRGB;
  if (bgra) *bgra = isBgra;
  return isBgra || isRgba;
}

gpu::Handle<VkSemaphore> makeSemaphore(const gpu::Context& context) {
  VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore semaphore = VK_NULL_HANDLE;
  VkDevice device = context.device();
  VK_CHECK(vkCreateSemaphore(device, &info, nullptr, &semaphore));
  return gpu::Handle<VkSemaphore>(
      semaphore, [device](VkSemaphore s) { vkDestroySemaphore(device, s, nullptr); });
}

Swapchain::Swapchain(const gpu::Context& context, VkSurfaceKHR surface, VkExtent2D framebuffer,
                     bool vsync, const Swapchain* previous)
    : context_(&context), vsync_(vsync) {
  VkPhysicalDevice physical = context.physicalDevice();
  // Some drivers answer with an error rather than VK_FALSE for a display they cannot drive.
  VkBool32 supported = VK_FALSE;
  VkResult support =
      vkGetPhysicalDeviceSurfaceSupportKHR(physical, context.queueFamily(), surface, &supported);
  if (support != VK_SUCCESS || !supported)
    fail(context.info().name, " cannot present to this window (", gpu::vkResultName(support),
         "); choose another device with --device or $THRONG_DEVICE, e.g. --device llvmpipe");

  VkSurfaceCapabilitiesKHR caps;
  VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface, &caps));
  uint32_t count = 0;
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()));
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(physical, surface, &count, modes.data()));

  VkSurfaceFormatKHR surfaceFormat = chooseSurfaceFormat(formats);
  format_ = surfaceFormat.format;
  presentMode_ = choosePresentMode(modes, vsync);
  extent_ = chooseExtent(caps, framebuffer);
  if (extent_.width == 0 || extent_.height == 0)
    fail("cannot create a swapchain for a minimised window");
  minImageCount_ = caps.minImageCount;
  canReadBack_ =
      (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) && isReadableFormat(format_);

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface;
  info.minImageCount = chooseImageCount(caps);
  info.imageFormat = surfaceFormat.format;
  info.imageColorSpace = surfaceFormat.colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (canReadBack_ ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = (caps.supportedTransforms & VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR)
                          ? VK_SURFACE_TRANSFORM_IDENTITY_BIT_KHR
                          : caps.currentTransform;
  info.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  for (VkCompositeAlphaFlagBitsKHR alpha :
       {VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR, VK_COMPOSITE_ALPHA_INHERIT_BIT_KHR,
        VK_COMPOSITE_ALPHA_PRE_MULTIPLIED_BIT_KHR, VK_COMPOSITE_ALPHA_POST_MULTIPLIED_BIT_KHR}) {
    if (caps.supportedCompositeAlpha & alpha) {
      info.compositeAlpha = alpha;
      break;
    }
  }
  info.presentMode = presentMode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = previous ? previous->swapchain_.get() : VK_NULL_HANDLE;
  VkDevice device = context.device();
  VkSwapchainKHR swapchain = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain));
  swapchain_ = gpu::Handle<VkSwapchainKHR>(
      swapchain, [device](VkSwapchainKHR s) { vkDestroySwapchainKHR(device, s, nullptr); });

  VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain, &count, nullptr));
  images_.resize(count);
  VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain, &count, images_.data()));
  for (VkImage image : images_) {
    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = image;
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = format_;
    viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
    views_.emplace_back(view, [device](VkImageView v) { vkDestroyImageView(device, v, nullptr); });
    rendered_.push_back(makeSemaphore(context));
  }
}

bool Swapchain::acquire(VkSemaphore acquired, uint32_t& index) const {
  constexpr uint64_t kTimeoutNs = 10'000'000'000ull;
  VkResult result = vkAcquireNextImageKHR(context_->device(), swapchain_, kTimeoutNs, acquired,
                                          VK_NULL_HANDLE, &index);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) return false;
  if (result == VK_TIMEOUT || result == VK_NOT_READY)
    fail("the window system gave no swapchain image for 10 s (", gpu::vkResultName(result), ")");
  // SUBOPTIMAL still signals the semaphore: draw this frame, present() then asks for a rebuild.
  if (result != VK_SUBOPTIMAL_KHR) VK_CHECK(result);
  return true;
}

bool Swapchain::present(uint32_t index) const {
  VkSemaphore wait = rendered_[index];
  VkSwapchainKHR swapchain = swapchain_;
  VkPresentInfoKHR info{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  info.waitSemaphoreCount = 1;
  info.pWaitSemaphores = &wait;
  info.swapchainCount = 1;
  info.pSwapchains = &swapchain;
  info.pImageIndices = &index;
  VkResult result = vkQueuePresentKHR(context_->queue(), &info);
  if (result == VK_ERROR_OUT_OF_DATE_KHR) return false;
  // SUBOPTIMAL: presented; some platforms report it for every frame, so the presenter rebuilds
  // on a size change rather than on this.
  if (result != VK_SUBOPTIMAL_KHR) VK_CHECK(result);
  return true;
}

}  // namespace throng::render
