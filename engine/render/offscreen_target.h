#pragma once
// Colour + depth images to render into without a window, and their readback to an image.
#include <string>
#include <vector>

#include "core/image.h"
#include "gpu/buffer.h"
#include "gpu/image.h"
#include "render/frame_targets.h"

namespace throng::render {

constexpr VkFormat kColorFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

struct OffscreenTarget {
  gpu::Image2D color;
  gpu::Image2D depth;
  // Host-visible copies of the colour image, one per slot: a frame loop reads one frame's pixels
  // out of one slot while the next frame is copied into the other.
  std::vector<gpu::Buffer> readbacks;
  uint32_t width = 0, height = 0;
};

// Checks a render target size against the device before anything is made or drawn at it:
// maxImageDimension2D and maxFramebufferWidth/Height for the images, and, where the renderer
// splats joints (64-bit atomics), its per-pixel visibility buffer (one uint64 a pixel, bound
// whole) against maxStorageBufferRange. Throws gpu::LimitError naming `what` and the limit.
void checkTargetSize(const gpu::Context& context, uint32_t width, uint32_t height,
                     const std::string& what);

// Throws Error for sizes outside 1..16384 or readback slots outside 1..2, gpu::LimitError past
// the device's limits.
OffscreenTarget makeOffscreenTarget(const gpu::Context& context, uint32_t width, uint32_t height,
                                    uint32_t readbackSlots = 1);

// The target's images as a frame's targets, left ready for recordReadback.
FrameTargets offscreenFrameTargets(const OffscreenTarget& target);

// Records the copy of the colour image (left in TRANSFER_SRC layout by the frame) to readback
// slot `slot`.
void recordReadback(VkCommandBuffer cmd, const OffscreenTarget& target, uint32_t slot = 0);
// After the commands completed: slot `slot`'s pixels as an image.
ImageRgba8 readbackImage(const OffscreenTarget& target, uint32_t slot = 0);
// The same into `image`, reusing its pixels' memory (a frame loop's recycled buffer).
void readbackInto(const OffscreenTarget& target, ImageRgba8& image, uint32_t slot = 0);

}  // namespace throng::render
