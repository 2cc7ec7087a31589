#pragma once
// The window platform of the frame loop: frames in flight over a swapchain. beginFrame()
// hands out a command buffer and the swapchain image as FrameTargets (the same targets
// scene::recordFrame draws into for the headless dumper); endFrame() presents it and can read
// the image back for a screenshot. Resize and minimise are handled here.
#include <functional>
#include <memory>
#include <optional>

#include "core/image.h"
#include "gpu/buffer.h"
#include "gpu/commands.h"
#include "gpu/image.h"
#include "gpu/timestamps.h"
#include "render/crowd_renderer.h"
#include "render/frame_targets.h"
#include "viewer/swapchain.h"
#include "viewer/window.h"

namespace throng::render {

// Two frames recorded ahead at most; stays below CrowdRenderer's uniform slots.
constexpr uint32_t kPresenterFrames = 2;
static_assert(kPresenterFrames <= kFramesInFlight,
              "every presenter frame needs its own renderer slot");

struct PresentFrame {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  uint32_t slot = 0;        // < kPresenterFrames: pass to scene::recordFrame as frameSlot
  uint32_t imageIndex = 0;  // the swapchain image being drawn
  FrameTargets targets;  // finalLayout COLOR_ATTACHMENT_OPTIMAL: overlays may draw after the crowd
  gpu::TimestampPool* timestamps = nullptr;  // reset and owned by this slot
};

class WindowPresenter {
 public:
  WindowPresenter(const gpu::Context& context, Window& window, bool vsync,
                  uint32_t timestampCapacity = 16);
  ~WindowPresenter();

  // Nullopt while the window is minimised (nothing to draw; wait for events). Before it
  // resets the slot's timestamps it calls `beforeReset(slot)` so their results can be read.
  std::optional<PresentFrame> beginFrame(
      const std::function<void(uint32_t slot)>& beforeReset = {});
  // Discards what was recorded into `frame` so far and begins its command buffer afresh (the
  // same image, slot and reset timestamps): for a frame whose recording threw.
  void restartFrame(const PresentFrame& frame);
  // Leaves the image in PRESENT_SRC, copying it to host memory first when `capture`.
  void endFrame(const PresentFrame& frame, bool capture);
  // The last captured frame (waits for it): RGBA, opaque.
  ImageRgba8 capturedImage();

  void setVsync(bool vsync);
  const Swapchain& swapchain() const { return *swapchain_; }
  // Changes whenever the swapchain was rebuilt (overlays rebuild their framebuffers).
  uint64_t generation() const { return generation_; }
  uint64_t rebuildCount() const { return generation_ - 1; }
  gpu::TimestampPool& timestamps(uint32_t slot) { return *slots_[slot].timestamps; }

 private:
  struct Slot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    std::unique_ptr<gpu::Fence> fence;
    gpu::Handle<VkSemaphore> acquired;
    std::unique_ptr<gpu::TimestampPool> timestamps;
    gpu::Image2D depth;
  };

  void rebuild();
  void beginCommands(Slot& slot);

  const gpu::Context& context_;
  Window& window_;
  gpu::Handle<VkSurfaceKHR> surface_;
  std::unique_ptr<Swapchain> swapchain_;
  gpu::CommandPool pool_;
  Slot slots_[kPresenterFrames];
  bool slotUsed_[kPresenterFrames] = {};
  uint32_t slot_ = 0;
  uint32_t imageIndex_ = 0;
  bool vsync_ = true;
  bool stale_ = false;
  uint64_t generation_ = 0;
  gpu::Buffer capture_;
  VkExtent2D captureExtent_{};
  bool captureBgra_ = false;
  bool captured_ = false;
};

}  // namespace throng::render
