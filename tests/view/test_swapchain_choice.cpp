// Swapchain choices that do not need a window: format, present mode (vsync), extent, count.
#include <doctest/doctest.h>

#include <vector>

#include "core/error.h"
#include "viewer/swapchain.h"

using namespace throng;

TEST_CASE("swapchain: a UNORM 8-bit format is preferred, as the headless target uses") {
  std::vector<VkSurfaceFormatKHR> formats = {
      {VK_FORMAT_B8G8R8A8_SRGB, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR},
      {VK_FORMAT_R8G8B8A8_UNORM, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR},
      {VK_FORMAT_B8G8R8A8_UNORM, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR}};
  CHECK(render::chooseSurfaceFormat(formats).format == VK_FORMAT_B8G8R8A8_UNORM);
  formats.pop_back();
  CHECK(render::chooseSurfaceFormat(formats).format == VK_FORMAT_R8G8B8A8_UNORM);
  formats.pop_back();
  CHECK(render::chooseSurfaceFormat(formats).format ==
        VK_FORMAT_B8G8R8A8_SRGB);  // whatever there is
  std::vector<VkSurfaceFormatKHR> anything = {
      {VK_FORMAT_UNDEFINED, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR}};
  CHECK(render::chooseSurfaceFormat(anything).format == VK_FORMAT_B8G8R8A8_UNORM);
  CHECK_THROWS_AS(render::chooseSurfaceFormat({}), Error);
}

TEST_CASE("swapchain: vsync is FIFO; without it MAILBOX, then IMMEDIATE, then FIFO") {
  std::vector<VkPresentModeKHR> all = {VK_PRESENT_MODE_IMMEDIATE_KHR, VK_PRESENT_MODE_MAILBOX_KHR,
                                       VK_PRESENT_MODE_FIFO_KHR};
  CHECK(render::choosePresentMode(all, true) == VK_PRESENT_MODE_FIFO_KHR);
  CHECK(render::choosePresentMode(all, false) == VK_PRESENT_MODE_MAILBOX_KHR);
  std::vector<VkPresentModeKHR> noMailbox = {VK_PRESENT_MODE_FIFO_KHR,
                                             VK_PRESENT_MODE_IMMEDIATE_KHR};
  CHECK(render::choosePresentMode(noMailbox, false) == VK_PRESENT_MODE_IMMEDIATE_KHR);
  std::vector<VkPresentModeKHR> fifoOnly = {VK_PRESENT_MODE_FIFO_KHR};
  CHECK(render::choosePresentMode(fifoOnly, false) == VK_PRESENT_MODE_FIFO_KHR);
}

TEST_CASE(
    "swapchain: extent follows the surface, else the framebuffer within limits; image count") {
  VkSurfaceCapabilitiesKHR caps{};
  caps.currentExtent = {800, 600};
  caps.minImageExtent = {1, 1};
  caps.maxImageExtent = {4096, 4096};
  caps.minImageCount = 2;
  caps.maxImageCount = 8;
  CHECK(render::chooseExtent(caps, {1024, 768}).width == 800);
  caps.currentExtent = {UINT32_MAX, UINT32_MAX};
  VkExtent2D e = render::chooseExtent(caps, {8000, 768});
  CHECK(e.width == 4096);
  CHECK(e.height == 768);
  CHECK(render::chooseImageCount(caps) == 3);
  caps.maxImageCount = 2;
  CHECK(render::chooseImageCount(caps) == 2);
  caps.maxImageCount = 0;  // no limit
  caps.minImageCount = 4;
  CHECK(render::chooseImageCount(caps) == 5);
}

TEST_CASE("swapchain: screenshots read 8-bit RGBA and BGRA images only") {
  bool bgra = false;
  CHECK(render::isReadableFormat(VK_FORMAT_B8G8R8A8_UNORM, &bgra));
  CHECK(bgra);
  CHECK(render::isReadableFormat(VK_FORMAT_R8G8B8A8_UNORM, &bgra));
  CHECK_FALSE(bgra);
  CHECK_FALSE(render::isReadableFormat(VK_FORMAT_A2B10G10R10_UNORM_PACK32));
  CHECK(std::string(render::presentModeName(VK_PRESENT_MODE_MAILBOX_KHR)) == "mailbox");
}
