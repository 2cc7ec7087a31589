#include "viewer/window_presenter.h"

#include <cstring>

#include "core/error.h"
#include "gpu/vk_check.h"
#include "render/offscreen_target.h"

namespace throng::render {

WindowPresenter::WindowPresenter(const gpu::Context& context, Window& window, bool vsync,
                                 uint32_t timestampCapacity)
    : context_(context),
      window_(window),
      surface_(window.createSurface(context.instance())),
      pool_(context),
      vsync_(vsync) {
  for (Slot& slot : slots_) {
    slot.cmd = pool_.allocate();
    slot.fence = std::make_unique<gpu::Fence>(context, true);
    slot.acquired = makeSemaphore(context);
    slot.timestamps = std::make_unique<gpu::TimestampPool>(context, timestampCapacity);
  }
  rebuild();
}

WindowPresenter::~WindowPresenter() {
  // Nothing may still use the swapchain, semaphores or command buffers we are about to free.
  vkDeviceWaitIdle(context_.device());
}

void WindowPresenter::rebuild() {
  context_.waitIdle();
  auto next = std::make_unique<Swapchain>(context_, surface_, window_.framebufferSize(), vsync_,
                                          swapchain_.get());
  swapchain_ = std::move(next);
  VkExtent2D extent = swapchain_->extent();
  checkTargetSize(context_, extent.width, extent.height,
                  concat("the window's ", extent.width, "x", extent.height, " swapchain"));
  for (Slot& slot : slots_)
    slot.depth =
        gpu::Image2D(context_, extent.width, extent.height, kDepthFormat,
                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);
  stale_ = false;
  ++generation_;
}

void WindowPresenter::setVsync(bool vsync) {
  if (vsync == vsync_) return;
  vsync_ = vsync;
  stale_ = true;
}

std::optional<PresentFrame> WindowPresenter::beginFrame(
    const std::function<void(uint32_t)>& beforeReset) {
  if (window_.minimized()) return std::nullopt;
  if (window_.takeResized()) stale_ = true;
  VkExtent2D size = window_.framebufferSize();
  if (size.width != swapchain_->extent().width || size.height != swapchain_->extent().height)
    stale_ = true;
  if (stale_) rebuild();

  Slot& slot = slots_[slot_];
  slot.fence->wait();
  // A swapchain can go out of date between the size check and the acquire: rebuild once more.
  uint32_t index = 0;
  if (!swapchain_->acquire(slot.acquired, index)) {
    rebuild();
    if (!swapchain_->acquire(slot.acquired, index)) return std::nullopt;
  }
  if (slotUsed_[slot_] && beforeReset) beforeReset(slot_);
  slot.fence->reset();
  slot.timestamps->reset();
  imageIndex_ = index;

  beginCommands(slot);

  PresentFrame frame;
  frame.cmd = slot.cmd;
  frame.slot = slot_;
  frame.imageIndex = index;
  frame.timestamps = slot.timestamps.get();
  VkExtent2D extent = swapchain_->extent();
  frame.targets = FrameTargets{swapchain_->image(index),
                               swapchain_->view(index),
                               slot.depth.get(),
                               slot.depth.view(),
                               extent.width,
                               extent.height,
                               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  return frame;
}

void WindowPresenter::beginCommands(Slot& slot) {
  gpu::beginCommands(slot.cmd);
  // The crowd state and joint buffers are updated in place every frame: the previous frame
  // (another command buffer, maybe still running) must finish with them first.
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  barrier.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(slot.cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                       VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void WindowPresenter::restartFrame(const PresentFrame& frame) {
  Slot& slot = slots_[frame.slot];
  VK_CHECK(vkResetCommandBuffer(slot.cmd, 0));  // the pool allows resetting one buffer
  slot.timestamps->reset();
  beginCommands(slot);
}

void WindowPresenter::endFrame(const PresentFrame& frame, bool capture) {
  Slot& slot = slots_[frame.slot];
  VkImage image = frame.targets.color;
  VkExtent2D extent{frame.targets.width, frame.targets.height};
  if (capture && !swapchain_->canReadBack())
    fail("this swapchain (format ", swapchain_->format(), ") cannot be read back for a screenshot");
  if (capture) {
    VkDeviceSize bytes = VkDeviceSize(extent.width) * extent.height * 4;
    if (!capture_ || capture_.size() != bytes) {
      context_.waitIdle();  // an earlier capture may still be writing the old buffer
      capture_ = gpu::Buffer(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             gpu::MemoryUse::HostVisible);
    }
    gpu::transitionImage(
        frame.cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
        VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vkCmdCopyImageToBuffer(frame.cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, capture_.get(),
                           1, &region);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(frame.cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                         1, &toHost, 0, nullptr, 0, nullptr);
    gpu::transitionImage(frame.cmd, image, VK_IMAGE_ASPECT_COLOR_BIT,
                         VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT,
                         0);
    captureExtent_ = extent;
    isReadableFormat(swapchain_->format(), &captureBgra_);
    captured_ = true;
  } else {
    gpu::transitionImage(
        frame.cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
  }
  gpu::endCommands(frame.cmd);

  // Everything waits for the acquire (the synthesis too): the crowd pass's first barrier
  // transitions the image from TOP_OF_PIPE, which a later wait stage would not cover.
  VkSemaphore wait = slot.acquired;
  VkSemaphore signal = swapchain_->renderedSemaphore(frame.imageIndex);
  VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_ALL_COMMANDS_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &wait;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &frame.cmd;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &signal;
  VK_CHECK(vkQueueSubmit(context_.queue(), 1, &submit, slot.fence->get()));
  slotUsed_[frame.slot] = true;
  if (!swapchain_->present(frame.imageIndex)) stale_ = true;
  slot_ = (slot_ + 1) % kPresenterFrames;
}

ImageRgba8 WindowPresenter::capturedImage() {
  if (!captured_) fail("no frame was captured");
  context_.waitIdle();
  ImageRgba8 image(static_cast<int>(captureExtent_.width), static_cast<int>(captureExtent_.height));
  std::memcpy(image.pixels.data(), capture_.mapped(), image.pixels.size() * sizeof(Rgba8));
  for (Rgba8& p : image.pixels) {
    if (captureBgra_) std::swap(p.r, p.b);
    p.a = 255;  // the window is opaque whatever alpha the passes left
  }
  return image;
}

}  // namespace throng::render
