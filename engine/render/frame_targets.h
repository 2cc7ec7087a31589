#pragma once
// The images a frame draws into: the offscreen target of headless runs or a swapchain image of
// the viewer (the same frame draws into either).
#include <cstdint>

#include <volk.h>

#include "gpu/buffer.h"

namespace throng::render {

struct FrameTargets {
  VkImage color = VK_NULL_HANDLE;
  VkImageView colorView = VK_NULL_HANDLE;
  VkImage depth = VK_NULL_HANDLE;
  VkImageView depthView = VK_NULL_HANDLE;
  uint32_t width = 0, height = 0;
  // TRANSFER_SRC_OPTIMAL for a readback by copy, GENERAL for one in place (a host-mapped image),
  // PRESENT_SRC_KHR for a swapchain, COLOR_ATTACHMENT_OPTIMAL when overlays draw after the crowd.
  VkImageLayout finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  // Colour and depth take transfer writes (TRANSFER_DST usage): while the view stands still, the
  // joint splat is then resolved by compute and copied in, instead of a full-screen fragment
  // pass.
  bool transferDst = false;
  // The colour image's texels as a storage buffer of rows width × 4 bytes apart (an offscreen
  // image read in place), or null: the splat's resolve then writes its colour plane there, and the
  // image is in VK_IMAGE_LAYOUT_GENERAL meanwhile.
  const gpu::Buffer* colorTexels = nullptr;
};

}  // namespace throng::render
