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

// How a frame's pixels reach the host. Copy: from the colour image into a host-visible buffer
// (a GPU's way: its images live in its own memory and layout). InPlace: the frame is drawn into a
// host-mapped colour image (linear tiling) that the host reads as it is: on a CPU device all
// memory is the host's, and the copy would be one more pass of the device's, on one core.
// Auto: InPlace on a CPU device that maps such an image, Copy otherwise.
enum class Readback { Auto, Copy, InPlace };

struct OffscreenTarget {
  // The colour images: one per readback slot when read in place, one otherwise.
  std::vector<gpu::Image2D> colors;
  gpu::Image2D depth;
  // Host-visible copies of the colour image, one per slot when copied, none in place: a frame
  // loop reads one frame's pixels out of one slot while the next frame goes to the other.
  std::vector<gpu::Buffer> readbacks;
  // Read in place with rows width × 4 bytes apart: each colour image's texels as a storage
  // buffer, which the splat's resolve writes instead of copying its colour plane in (one copy of
  // the frame fewer); empty otherwise. Declared after `colors`, so destroyed before them.
  std::vector<gpu::Buffer> colorTexels;
  uint32_t width = 0, height = 0;

  bool inPlace() const { return readbacks.empty(); }
  // The colour image that a frame for readback slot `slot` draws into.
  const gpu::Image2D& color(uint32_t slot = 0) const;
};

// Checks a render target size against the device before anything is made or drawn at it:
// maxImageDimension2D and maxFramebufferWidth/Height for the images, and, where the renderer
// splats joints (64-bit atomics), its per-pixel visibility buffer (one uint64 a pixel, bound
// whole) against maxStorageBufferRange. Throws gpu::LimitError naming `what` and the limit.
void checkTargetSize(const gpu::Context& context, uint32_t width, uint32_t height,
                     const std::string& what);

// Throws Error for sizes outside 1..16384, readback slots outside 1..2 or an InPlace readback the
// device cannot map, gpu::LimitError past the device's limits.
OffscreenTarget makeOffscreenTarget(const gpu::Context& context, uint32_t width, uint32_t height,
                                    uint32_t readbackSlots = 1, Readback readback = Readback::Auto);

// The layout a frame leaves the colour image in for recordReadback: TRANSFER_SRC_OPTIMAL to copy
// it, GENERAL to read it in place.
VkImageLayout readbackLayout(const OffscreenTarget& target);

// The target's images for readback slot `slot` as a frame's targets, left ready for
// recordReadback.
FrameTargets offscreenFrameTargets(const OffscreenTarget& target, uint32_t slot = 0);

// Records what makes slot `slot`'s pixels the host's once the commands complete: the copy of the
// colour image (left in readbackLayout by the frame) to the slot's buffer, or, in place, the
// barrier to the host's reads.
void recordReadback(VkCommandBuffer cmd, const OffscreenTarget& target, uint32_t slot = 0);
// After the commands completed: slot `slot`'s pixels as an image.
ImageRgba8 readbackImage(const OffscreenTarget& target, uint32_t slot = 0);
// The same into `image`, reusing its pixels' memory (a frame loop's recycled buffer).
void readbackInto(const OffscreenTarget& target, ImageRgba8& image, uint32_t slot = 0);

}  // namespace throng::render
