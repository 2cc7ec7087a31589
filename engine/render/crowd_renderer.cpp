#include "render/crowd_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "core/error.h"
#include "synth/gpu_types.h"

namespace throng::render {

using gpu_types::DrawPush;
using gpu_types::FrameUniforms;
static_assert(sizeof(DrawPush) == 16, "DrawPush must match the GLSL push block");
static_assert(sizeof(FrameUniforms) == 160, "FrameUniforms must match the GLSL std140 block");

namespace {
FrameUniforms makeFrameUniforms(const DrawParams& params) {
  const Camera& camera = params.camera;
  float aspect = float(params.width) / float(params.height);
  float tanY = std::tan(0.5f * glm::radians(camera.fovYDegrees));
  glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
  glm::vec3 up = glm::cross(right, forward);
  FrameUniforms u{};
  u.viewProjection = camera.viewProjection(aspect);
  u.eye = glm::vec4(camera.eye, params.groundExtent);
  u.lightDirection = glm::vec4(glm::normalize(glm::vec3(0.45f, 0.8f, -0.35f)), 0.0f);
  u.rayRight = glm::vec4(right * tanY * aspect, 0.0f);
  u.rayDown = glm::vec4(-up * tanY, 0.0f);
  u.rayForward = glm::vec4(forward, 0.0f);
  u.viewport = glm::vec4(float(params.width), float(params.height), camera.focalLengthPixels(float(params.height)), 0.0f);
  return u;
}
}  // namespace

CrowdRenderer::CrowdRenderer(const gpu::Context& context, VkFormat colorFormat, VkFormat depthFormat) {
  gpu::GraphicsPipelineDesc jointDesc;
  jointDesc.vertexShader = "joints.vert";
  jointDesc.fragmentShader = "joints.frag";
  jointDesc.colorFormat = colorFormat;
  jointDesc.depthFormat = depthFormat;
  jointDesc.cullMode = VK_CULL_MODE_NONE;
  jointDesc.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
  joints_ = gpu::GraphicsProgram(context, jointDesc);
  gpu::GraphicsPipelineDesc groundDesc = jointDesc;
  groundDesc.vertexShader = "ground.vert";
  groundDesc.fragmentShader = "ground.frag";
  groundDesc.cullMode = VK_CULL_MODE_NONE;
  groundDesc.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  ground_ = gpu::GraphicsProgram(context, groundDesc);

  for (uint32_t i = 0; i < kFramesInFlight; ++i)
    frameUniforms_.emplace_back(context, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                gpu::MemoryUse::HostVisible);
  // One draw may bind at most maxStorageBufferRange bytes of joint matrices (128 MiB on lavapipe).
  maxCharactersPerDraw_ = context.info().maxStorageBufferRange / 48u;
}

void CrowdRenderer::record(VkCommandBuffer cmd, VkImage color, VkImageView colorView, VkImage depth,
                           VkImageView depthView, const DrawParams& params, VkImageLayout finalLayout,
                           uint32_t frameSlot) const {
  THRONG_CHECK(frameSlot < kFramesInFlight, "frame slot ", frameSlot, " out of range");
  const gpu::Buffer& uniforms = frameUniforms_[frameSlot];
  FrameUniforms frame = makeFrameUniforms(params);
  std::memcpy(uniforms.mapped(), &frame, sizeof(frame));
  if (params.characterCount > 0 && (!params.joints || params.jointCount == 0))
    fail("CrowdRenderer: joint matrices are missing for ", params.characterCount, " characters");
  gpu::transitionImage(cmd, color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT);
  gpu::transitionImage(cmd, depth, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                       VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL_KHR, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                       VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT,
                       VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT);

  VkRenderingAttachmentInfoKHR colorAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR};
  colorAttachment.imageView = colorView;
  colorAttachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  colorAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  colorAttachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  colorAttachment.clearValue.color = params.clearColor;
  VkRenderingAttachmentInfoKHR depthAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR};
  depthAttachment.imageView = depthView;
  depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL_KHR;
  depthAttachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depthAttachment.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depthAttachment.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfoKHR rendering{VK_STRUCTURE_TYPE_RENDERING_INFO_KHR};
  rendering.renderArea = {{0, 0}, {params.width, params.height}};
  rendering.layerCount = 1;
  rendering.colorAttachmentCount = 1;
  rendering.pColorAttachments = &colorAttachment;
  rendering.pDepthAttachment = &depthAttachment;
  vkCmdBeginRenderingKHR(cmd, &rendering);

  VkViewport viewport{0.0f, 0.0f, float(params.width), float(params.height), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, {params.width, params.height}};
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);

  gpu::Binding groundBindings[] = {gpu::uniformBinding(1, uniforms)};
  ground_.bind(cmd, groundBindings, nullptr, 0);
  vkCmdDraw(cmd, 6, 1, 0, 0);

  DrawPush push{};
  push.jointCount = params.jointCount;
  const uint32_t perDraw = std::max(1u, maxCharactersPerDraw_ / std::max(1u, params.jointCount));
  for (uint32_t first = 0; first < params.characterCount; first += perDraw) {
    uint32_t count = std::min(perDraw, params.characterCount - first);
    VkDeviceSize bytes = VkDeviceSize(count) * params.jointCount * 48u;
    VkDeviceSize offset = VkDeviceSize(first) * params.jointCount * 48u;
    gpu::Binding bindings[] = {gpu::storageBinding(0, *params.joints, offset, bytes), gpu::uniformBinding(1, uniforms)};
    push.firstCharacter = first;
    joints_.bind(cmd, bindings, &push, sizeof(push));
    vkCmdDraw(cmd, count * params.jointCount, 1, 0, 0);
  }
  vkCmdEndRenderingKHR(cmd);

  VkAccessFlags dstAccess = finalLayout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL ? VK_ACCESS_TRANSFER_READ_BIT : 0;
  VkPipelineStageFlags dstStage = finalLayout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL
                                      ? VK_PIPELINE_STAGE_TRANSFER_BIT
                                      : VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT;
  gpu::transitionImage(cmd, color, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, finalLayout,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, dstStage,
                       dstAccess);
}

}  // namespace throng::render
