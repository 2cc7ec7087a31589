#pragma once
// The one graphics pipeline that draws every joint of every character as an instanced
// ellipsoid (a ray-cast quad), plus the ground. Records into any colour/depth image pair (offscreen target or
// swapchain image), so the viewer and the frame dumper share it.
#include <vector>

#include "gpu/buffer.h"
#include "gpu/graphics_pipeline.h"
#include "gpu/image.h"
#include "render/camera.h"

namespace throng::render {

struct DrawParams {
  Camera camera;
  uint32_t width = 0, height = 0;
  uint32_t characterCount = 0;
  uint32_t jointCount = 0;
  const gpu::Buffer* joints = nullptr;  // JointMatrix per character per joint
  float groundExtent = 100.0f;
  VkClearColorValue clearColor{{0.55f, 0.66f, 0.78f, 1.0f}};
};

// Frames that may be recorded before the first of them completes (uniform buffers per frame).
constexpr uint32_t kFramesInFlight = 3;

class CrowdRenderer {
 public:
  CrowdRenderer(const gpu::Context& context, VkFormat colorFormat, VkFormat depthFormat);

  // Transitions `color` from UNDEFINED to COLOR_ATTACHMENT, draws, and leaves it in `finalLayout`
  // (TRANSFER_SRC_OPTIMAL for readback, PRESENT_SRC_KHR for a swapchain).
  // `frameSlot` < kFramesInFlight picks the uniform buffer; reuse a slot only after the frame
  // that last used it has completed.
  void record(VkCommandBuffer cmd, VkImage color, VkImageView colorView, VkImage depth, VkImageView depthView,
              const DrawParams& params, VkImageLayout finalLayout, uint32_t frameSlot = 0) const;

 private:
  gpu::GraphicsProgram joints_;
  gpu::GraphicsProgram ground_;
  std::vector<gpu::Buffer> frameUniforms_;
  uint32_t maxCharactersPerDraw_ = 0;
};

}  // namespace throng::render
