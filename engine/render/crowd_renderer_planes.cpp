// CrowdRenderer's start of a frame on its offscreen path: the ground's words, kept while the
// view stands still, and the splat resolved into the target's colour and depth planes.
#include "core/error.h"
#include "gpu/commands.h"
#include "render/crowd_renderer.h"
#include "shaders/render_bindings.h"
#include "synth/gpu_types.h"

namespace throng::render {

using gpu_types::FrameUniforms;

bool CrowdRenderer::planesInTarget(const FrameTargets& target, const DrawParams& params) {
  return target.colorTexels && !depthPlane(params);
}

void CrowdRenderer::clearTargets(VkCommandBuffer cmd, const FrameTargets& target) {
  const VkImage color = target.color, depth = target.depth;
  gpu::transitionImage(cmd, color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                       0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  gpu::transitionImage(
      cmd, depth, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
      VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL_KHR, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
      VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
}

bool CrowdRenderer::groundFor(VkCommandBuffer cmd, const DrawParams& params, uint32_t frameSlot) {
  std::vector<uint8_t> key(sizeof(FrameUniforms) + sizeof(VkClearColorValue));
  const FrameUniforms frame = makeFrameUniforms(params);
  std::memcpy(key.data(), &frame, sizeof(frame));
  std::memcpy(key.data() + sizeof(frame), &params.clearColor, sizeof(VkClearColorValue));
  if (groundVisibility_ && key == groundKey_) {
    previousKey_ = key;
    return true;
  }
  // A camera that moves every frame never pays for a ground it would use once: it is made when
  // the same view comes twice in a row, or at once when the caller says it stays.
  const bool again = key == previousKey_;
  previousKey_ = key;
  if (!again && !params.stillView) return false;
  const VkDeviceSize pixels = VkDeviceSize(params.width) * params.height;
  const VkDeviceSize groundBytes = pixels * sizeof(uint64_t);
  if (!groundVisibility_ || groundVisibility_.size() != groundBytes) {
    if (groundVisibility_) {
      retiredVisibility_.emplace_back(std::move(groundVisibility_), kFramesInFlight + 1);
      retiredVisibility_.emplace_back(std::move(framePlanes_), kFramesInFlight + 1);
    }
    const VkBufferUsageFlags usage =
        gpu::kStorageUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    groundVisibility_ = gpu::Buffer(*context_, groundBytes, usage, gpu::MemoryUse::DeviceLocal);
    const VkDeviceSize planeWords =
        gpu_types::visibilityDepthPlane(uint32_t(pixels)) + VkDeviceSize(pixels);
    framePlanes_ =
        gpu::Buffer(*context_, planeWords * sizeof(uint32_t), usage, gpu::MemoryUse::DeviceLocal);
  }
  // Earlier frames' copies read the ground.
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  // The ground is this view's once the frame that makes it is recorded whole (endDraw): a frame
  // that fails while recording is never submitted, and its ground never made.
  groundKey_.clear();
  pendingGroundKey_ = key;
  gpu::Binding bindings[] = {
      gpu::uniformBinding(gpu_types::kRenderBindingFrame, frameUniforms_[frameSlot]),
      gpu::storageBinding(gpu_types::kRenderBindingGroundVisibility, groundVisibility_)};
  const VkClearColorValue& clear = params.clearColor;
  const float clearColour[4] = {clear.float32[0], clear.float32[1], clear.float32[2],
                                clear.float32[3]};
  // A workgroup per 64 pixels of a row, at most 16384 (the shader strides over the rest).
  const uint32_t groups = std::min((params.width + 63u) / 64u * params.height, 16384u);
  gpu::dispatch(cmd, groundProgram_, bindings, clearColour, sizeof(clearColour),
                groups * groundProgram_.localSizeX());
  passTimer_->mark(cmd, "ground-words");
  return true;
}

void CrowdRenderer::resolvePlanes(VkCommandBuffer cmd, const FrameTargets& target,
                                  const DrawParams& params, uint32_t frameSlot) {
  // The splat's passes (and anything splatting between recordSplat and beginDraw) wrote the
  // visibility buffer; the previous frame's copy out of the planes read them.
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
  const bool inTarget = planesInTarget(target, params);
  if (inTarget)  // its previous contents are overwritten whole
    gpu::transitionImage(cmd, target.color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT);
  gpu::Binding bindings[] = {
      gpu::uniformBinding(gpu_types::kRenderBindingFrame, frameUniforms_[frameSlot]),
      gpu::uniformTexelBinding(gpu_types::kRenderBindingVisibility, visibilityTexels_.get()),
      gpu::storageBinding(gpu_types::kRenderBindingFramePlanes,
                          inTarget ? *target.colorTexels : framePlanes_)};
  // Four pixels per invocation, at most kPlanesGroups workgroups striding over the rest: lavapipe
  // pays for every workgroup it starts.
  const uint32_t quads = (params.width * params.height + 3u) / 4u;
  const uint32_t groups = std::min((quads + 63u) / 64u, gpu_types::kPlanesGroups);
  const uint32_t planes = depthPlane(params) ? gpu_types::kPlanesWithDepth : 0u;
  gpu::dispatch(cmd, planesProgram_, bindings, &planes, sizeof(planes),
                groups * planesProgram_.localSizeX());
  // The copies read the planes; without the depth plane the near joints read the visibility
  // buffer.
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
  passTimer_->mark(cmd, "splat-resolve");
}

void CrowdRenderer::copyPlanesIn(VkCommandBuffer cmd, const FrameTargets& target,
                                 const DrawParams& params) {
  VkBufferImageCopy region{};
  region.imageExtent = {params.width, params.height, 1};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  if (planesInTarget(target, params)) {  // written in place: only the layout changes
    gpu::transitionImage(
        cmd, target.color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_GENERAL,
        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
        VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  } else {
    gpu::transitionImage(cmd, target.color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdCopyBufferToImage(cmd, framePlanes_.get(), target.color,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    gpu::transitionImage(
        cmd, target.color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
        VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
        VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  }
  if (!depthPlane(params)) {  // cleared when the render pass begins
    gpu::transitionImage(
        cmd, target.depth, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
        VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL_KHR, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
        VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
        VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
    passTimer_->mark(cmd, "planes-copy");
    return;
  }
  gpu::transitionImage(cmd, target.depth, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                       VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
  region.bufferOffset =
      VkDeviceSize(gpu_types::visibilityDepthPlane(params.width * params.height)) * 4u;
  region.imageSubresource = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 0, 1};
  vkCmdCopyBufferToImage(cmd, framePlanes_.get(), target.depth,
                         VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  gpu::transitionImage(
      cmd, target.depth, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
      VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT,
      VK_ACCESS_TRANSFER_WRITE_BIT,
      VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
      VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT);
  passTimer_->mark(cmd, "planes-copy");
}

}  // namespace throng::render
