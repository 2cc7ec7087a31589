#pragma once
// Dear ImGui on top of the presented frame: Debian's ImGui 1.86 with its GLFW and Vulkan
// backends. The 1.86 Vulkan backend draws inside a render pass (no dynamic rendering), so
// this owns a LOAD/STORE render pass over the swapchain format and one framebuffer per image.
// Callers build widgets with ImGui:: calls between newFrame() and record().
#include <vector>

#include "gpu/context.h"
#include "gpu/handle.h"
#include "viewer/swapchain.h"
#include "viewer/window.h"

namespace throng::render {

class ImGuiLayer {
 public:
  ImGuiLayer(const gpu::Context& context, Window& window, const Swapchain& swapchain,
             uint32_t framesInFlight);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  void newFrame();
  // Finishes the ImGui frame and draws it over swapchain image `imageIndex`, which must be in
  // COLOR_ATTACHMENT_OPTIMAL and stays there. Rebuilds framebuffers when `generation` changed.
  void record(VkCommandBuffer cmd, const Swapchain& swapchain, uint32_t imageIndex,
              uint64_t generation);
  // Ends a frame begun with newFrame() without drawing it (the panel was hidden meanwhile).
  void discardFrame();

  // Whether ImGui wants the mouse / keyboard (the camera must not react then).
  bool wantsMouse() const;
  bool wantsKeyboard() const;

 private:
  void rebuildFramebuffers(const Swapchain& swapchain);

  const gpu::Context& context_;
  gpu::Handle<VkDescriptorPool> descriptorPool_;
  gpu::Handle<VkRenderPass> renderPass_;
  std::vector<gpu::Handle<VkFramebuffer>> framebuffers_;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  uint64_t generation_ = 0;
  bool frameOpen_ = false;
  bool backendsReady_[2] = {false, false};  // glfw, vulkan
};

}  // namespace throng::render
