#include "render/crowd_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <initializer_list>
#include <utility>

#include "core/error.h"
#include "gpu/commands.h"
#include "render/joint_splat.h"
#include "shaders/render_bindings.h"
#include "shaders/synth_bindings.h"
#include "synth/coverage.h"
#include "synth/gpu_types.h"

namespace throng::render {

using gpu_types::DrawPush;
using gpu_types::FrameUniforms;
using gpu_types::kDrawFromList;
static_assert(sizeof(DrawPush) == 24, "DrawPush must match the GLSL push block");
static_assert(sizeof(FrameUniforms) == 224, "FrameUniforms must match the GLSL std140 block");

namespace {

uint32_t drawFlags(const DrawParams& params) {
  uint32_t flags = 0;
  if (params.masks) flags |= gpu_types::kDrawUseMasks;
  if (params.masks && params.tintLevels) flags |= gpu_types::kDrawTintLevel;
  if (params.masks && params.lodLevels) flags |= gpu_types::kDrawLodLevels;
  if (params.groups) flags |= gpu_types::kDrawGroupTint;
  if (params.cachedPoses.enabled()) flags |= gpu_types::kDrawCachedPoses;
  return flags;
}

// The given inputs, or the placeholder for each binding the shaders declare but will not read.
CachedPoseInputs boundCachedPoses(const DrawParams& params, const gpu::Buffer& placeholder) {
  CachedPoseInputs bound =
      params.cachedPoses.enabled()
          ? params.cachedPoses
          : CachedPoseInputs{&placeholder, &placeholder, &placeholder, &placeholder};
  if (!bound.farBodyPoses) bound.farBodyPoses = &placeholder;
  return bound;
}

// The splat's passes keep 64-bit atomic minima and share work within subgroups (arithmetic,
// ballot, shuffles); a device without them draws every joint by the graphics pipeline.
bool splatSupportedBy(const gpu::DeviceInfo& info) {
  const VkSubgroupFeatureFlags needed =
      VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT |
      VK_SUBGROUP_FEATURE_BALLOT_BIT | VK_SUBGROUP_FEATURE_SHUFFLE_BIT;
  return info.int64Atomics && (info.computeSubgroupOperations & needed) == needed;
}
}  // namespace

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
  u.viewport = glm::vec4(float(params.width), float(params.height),
                         camera.focalLengthPixels(float(params.height)), 0.0f);
  if (params.characterCount > 0 && params.jointParents.size() != params.jointCount)
    fail("draw: ", params.jointParents.size(), " joint parents for ", params.jointCount, " joints");
  for (uint32_t j = 0; j < gpu_types::kPoseMaxJoints; ++j) {
    const int32_t parent = j < params.jointParents.size() ? params.jointParents[j] : -1;
    const uint32_t byte = parent < 0 ? gpu_types::kNoParent : uint32_t(parent);
    u.jointParents[j / 16u][(j / 4u) % 4u] |= byte << (8u * (j % 4u));
  }
  return u;
}

CrowdRenderer::CrowdRenderer(const gpu::Context& context, VkFormat colorFormat,
                             VkFormat depthFormat)
    : context_(&context),
      splatSupported_(splatSupportedBy(context.info())),
      splatWalk_(splatWalkFor(context.info())),
      passTimer_(std::make_unique<PassTimer>(context)) {
  gpu::GraphicsPipelineDesc jointDesc;
  jointDesc.vertexShader = "joints.vert";
  jointDesc.fragmentShader = "joints.frag";
  jointDesc.colorFormat = colorFormat;
  jointDesc.depthFormat = depthFormat;
  jointDesc.cullMode = VK_CULL_MODE_NONE;
  jointDesc.topology = VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
  joints_ = gpu::GraphicsProgram(context, jointDesc);
  gpu::GraphicsPipelineDesc overSplatDesc = jointDesc;
  overSplatDesc.fragmentShader = "joints_over_splat.frag";
  jointsOverSplat_ = gpu::GraphicsProgram(context, overSplatDesc);
  gpu::GraphicsPipelineDesc groundDesc = jointDesc;
  groundDesc.vertexShader = "ground.vert";
  groundDesc.fragmentShader = "ground.frag";
  groundDesc.cullMode = VK_CULL_MODE_NONE;
  groundDesc.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  ground_ = gpu::GraphicsProgram(context, groundDesc);
  gpu::GraphicsPipelineDesc wallDesc = groundDesc;
  wallDesc.vertexShader = "walls.vert";
  wallDesc.fragmentShader = "walls.frag";
  walls_ = gpu::GraphicsProgram(context, wallDesc);

  if (splatSupported_) {
    const SplatCapacity capacity = splatCapacityFor(splatWalk_);
    splat_ = makeSplatPrograms(context, splatWalk_, capacity.sprites, capacity.pixels);
    splatLists_ = makeSplatLists(context, capacity.sprites, capacity.pixels);
    groundProgram_ = gpu::ComputeProgram(context, "ground.comp");
    planesProgram_ = gpu::ComputeProgram(context, "visibility_planes.comp");
    gpu::GraphicsPipelineDesc resolveDesc = groundDesc;
    resolveDesc.vertexShader = "splat_resolve.vert";
    resolveDesc.fragmentShader = "splat_resolve.frag";
    resolve_ = gpu::GraphicsProgram(context, resolveDesc);
  }
  noMasks_ = gpu::Buffer(context, 16, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  noLodLevels_ = gpu::Buffer(context, sizeof(gpu_types::CoverageParts),
                             VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, gpu::MemoryUse::HostVisible);
  std::memset(noLodLevels_.mapped(), 0, sizeof(gpu_types::CoverageParts));
  for (uint32_t i = 0; i < kFramesInFlight; ++i)
    frameUniforms_.emplace_back(context, sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                gpu::MemoryUse::HostVisible);
}

bool CrowdRenderer::depthPlane(const DrawParams& params) {
  return params.wallSegmentCount > 0 || params.moreDepthDraws;
}

void CrowdRenderer::ensureVisibility(uint32_t width, uint32_t height) {
  const auto age = [](auto& retired) {  // one record closer to freeing each
    for (auto it = retired.begin(); it != retired.end();)
      it = --it->second == 0 ? retired.erase(it) : std::next(it);
  };
  age(retiredVisibility_);
  age(retiredViews_);
  if (visibility_ && visibilityWidth_ == width && visibilityHeight_ == height) return;
  if (visibility_) {
    retiredVisibility_.emplace_back(std::move(visibility_), kFramesInFlight + 1);
    retiredViews_.emplace_back(std::move(visibilityTexels_), kFramesInFlight + 1);
  }
  // Whole texels of two pixels (an odd pixel count's last one in a texel of its own);
  // makeBufferView refuses a frame past the device's texel limit.
  const VkDeviceSize pairs = (VkDeviceSize(width) * height + 1) / 2;
  visibility_ = gpu::Buffer(*context_, pairs * 2 * sizeof(uint64_t),
                            gpu::kStorageUsage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                            gpu::MemoryUse::DeviceLocal);
  visibilityTexels_ = gpu::makeBufferView(*context_, visibility_, VK_FORMAT_R32G32B32A32_UINT);
  visibilityWidth_ = width;
  visibilityHeight_ = height;
}

void CrowdRenderer::ensureLists(uint32_t characterCount, uint32_t jointCount) {
  VkDeviceSize listBytes =
      std::max<VkDeviceSize>(16, VkDeviceSize(characterCount) * jointCount * 4);
  size_t chunks =
      jointChunks(characterCount, jointCount, context_->info().maxStorageBufferRange).size();
  VkDeviceSize drawBytes = std::max<VkDeviceSize>(16, chunks * 16);
  // Lists only grow; a smaller crowd keeps the larger buffers.
  if (!nearList_ || nearList_.size() < listBytes) {
    if (nearList_) retiredVisibility_.emplace_back(std::move(nearList_), kFramesInFlight + 1);
    nearList_ = gpu::Buffer(*context_, listBytes, gpu::kStorageUsage, gpu::MemoryUse::DeviceLocal);
  }
  const VkDeviceSize characterListBytes =
      std::max<VkDeviceSize>(16, VkDeviceSize(characterCount) * 4);
  for (gpu::Buffer* list : {&onScreenList_, &walkList_})
    if (!*list || list->size() < characterListBytes) {
      if (*list) retiredVisibility_.emplace_back(std::move(*list), kFramesInFlight + 1);
      *list = gpu::Buffer(*context_, characterListBytes, gpu::kStorageUsage,
                          gpu::MemoryUse::DeviceLocal);
    }
  if (!listCounts_ || listCounts_.size() < listCountsBytes(chunks)) {
    if (listCounts_) retiredVisibility_.emplace_back(std::move(listCounts_), kFramesInFlight + 1);
    listCounts_ = gpu::Buffer(*context_, listCountsBytes(chunks),
                              gpu::kStorageUsage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                              gpu::MemoryUse::DeviceLocal);
  }
  if (!draws_ || draws_.size() < drawBytes) {
    if (draws_) retiredVisibility_.emplace_back(std::move(draws_), kFramesInFlight + 1);
    draws_ =
        gpu::Buffer(*context_, drawBytes, gpu::kStorageUsage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT,
                    gpu::MemoryUse::DeviceLocal);
  }
}

bool CrowdRenderer::splats(const DrawParams& params) const {
  return splatSupported_ && params.splatMaxPixels > 0.0f && params.characterCount > 0;
}

const gpu::Buffer* CrowdRenderer::recordSplat(VkCommandBuffer cmd, const FrameTargets& target,
                                              const DrawParams& params, uint32_t frameSlot) {
  THRONG_CHECK(frameSlot < kFramesInFlight, "frame slot ", frameSlot, " out of range");
  passTimer_->beginFrame(cmd);
  const gpu::Buffer& uniforms = frameUniforms_[frameSlot];
  FrameUniforms frame = makeFrameUniforms(params);
  std::memcpy(uniforms.mapped(), &frame, sizeof(frame));
  const bool splat = splats(params);
  const gpu::Buffer* lodLevels =
      params.masks && params.lodLevels ? params.lodLevels : &noLodLevels_;
  ensureLists(params.characterCount, params.jointCount);
  groundCopied_ = splat && target.transferDst && groundFor(cmd, params, frameSlot);
  if (splat) {
    ensureVisibility(params.width, params.height);
    SplatJob job{params.joints,
                 &uniforms,
                 &visibility_,
                 &draws_,
                 &nearList_,
                 params.width,
                 params.height,
                 params.characterCount,
                 params.jointCount,
                 params.splatMaxPixels,
                 context_->info().maxStorageBufferRange,
                 params.masks ? params.masks : &noMasks_,
                 drawFlags(params),
                 boundCachedPoses(params, noMasks_),
                 params.groups,
                 params.drawnBones,
                 lodLevels,
                 passTimer_.get(),
                 &splatLists_.sprites,
                 &splatLists_.pixelOwners,
                 &splatLists_.counters};
    job.onScreenList = &onScreenList_;
    job.walkList = &walkList_;
    job.listCounts = &listCounts_;
    job.walk = splatWalk_;
    const SplatCapacity capacity = splatCapacityFor(splatWalk_);
    job.spriteCapacity = capacity.sprites;
    job.pixelCapacity = capacity.pixels;
    job.initialVisibility = groundCopied_ ? &groundVisibility_ : nullptr;
    job.record(cmd, splat_);
    return &visibility_;
  }
  return nullptr;
}

void CrowdRenderer::beginDraw(VkCommandBuffer cmd, const FrameTargets& target,
                              const DrawParams& params, uint32_t frameSlot) {
  THRONG_CHECK(frameSlot < kFramesInFlight, "frame slot ", frameSlot, " out of range");
  passTimer_->mark(cmd, "before-pass");
  if (params.characterCount > 0 && (!params.joints || params.jointCount == 0))
    fail("CrowdRenderer: joint points are missing for ", params.characterCount, " characters");
  THRONG_CHECK(!groundCopied_ || target.transferDst,
               "beginDraw: the splat started from the ground, for a target that takes copies");
  if (groundCopied_) {
    resolvePlanes(cmd, target, params, frameSlot);
    copyPlanesIn(cmd, target, params);
  } else {
    clearTargets(cmd, target);
  }
  beginRendering(cmd, target, params, groundCopied_, groundCopied_ && depthPlane(params));
  drawJoints(cmd, params, frameSlot);
}

void CrowdRenderer::beginRendering(VkCommandBuffer cmd, const FrameTargets& target,
                                   const DrawParams& params, bool loadColour, bool loadDepth) {
  VkRenderingAttachmentInfoKHR colorAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR};
  colorAttachment.imageView = target.colorView;
  colorAttachment.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  colorAttachment.loadOp = loadColour ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
  colorAttachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  colorAttachment.clearValue.color = params.clearColor;
  VkRenderingAttachmentInfoKHR depthAttachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO_KHR};
  depthAttachment.imageView = target.depthView;
  depthAttachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL_KHR;
  depthAttachment.loadOp = loadDepth ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR;
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
}

void CrowdRenderer::drawJoints(VkCommandBuffer cmd, const DrawParams& params, uint32_t frameSlot) {
  const gpu::Buffer& uniforms = frameUniforms_[frameSlot];
  const bool splat = splats(params);
  if (!splat) {  // with the splat, the ground is in its resolve
    gpu::Binding groundBindings[] = {gpu::uniformBinding(gpu_types::kRenderBindingFrame, uniforms)};
    ground_.bind(cmd, groundBindings, nullptr, 0);
    vkCmdDraw(cmd, 6, 1, 0, 0);
    passTimer_->mark(cmd, "ground");
  }
  if (params.wallSegmentCount > 0) {
    gpu::Binding wallBindings[] = {
        gpu::uniformBinding(gpu_types::kRenderBindingFrame, uniforms),
        gpu::uniformTexelBinding(gpu_types::kRenderBindingWalls, params.wallSegments)};
    walls_.bind(cmd, wallBindings, nullptr, 0);
    vkCmdDraw(cmd, 6 * params.wallSegmentCount, 1, 0, 0);
  }
  drawNearJoints(cmd, params, uniforms);
  passTimer_->mark(cmd, "near-joints");
  if (splat && !groundCopied_) {  // otherwise the planes copied in hold the splat
    gpu::Binding resolveBindings[] = {
        gpu::uniformBinding(gpu_types::kRenderBindingFrame, uniforms),
        gpu::storageBinding(gpu_types::kRenderBindingVisibility, visibility_)};
    resolve_.bind(cmd, resolveBindings, nullptr, 0);
    vkCmdDraw(cmd, 3, 1, 0, 0);
    passTimer_->mark(cmd, "resolve");
  }
}

void CrowdRenderer::drawNearJoints(VkCommandBuffer cmd, const DrawParams& params,
                                   const gpu::Buffer& uniforms) {
  const bool splat = splats(params);
  const gpu::Buffer* lodLevels =
      params.masks && params.lodLevels ? params.lodLevels : &noLodLevels_;
  DrawPush push{};
  push.jointCount = params.jointCount;
  push.flags = (splat ? kDrawFromList : 0u) | drawFlags(params);
  push.boneLo = uint32_t(params.drawnBones);
  push.boneHi = uint32_t(params.drawnBones >> 32);
  const std::vector<JointChunk> chunks =
      jointChunks(params.characterCount, params.jointCount, context_->info().maxStorageBufferRange);
  const VkDeviceSize perCharacter = VkDeviceSize(params.jointCount) * sizeof(gpu_types::JointPoint);
  const CachedPoseInputs cached = boundCachedPoses(params, noMasks_);
  // Over the planes without their depths, the near joints test against the visibility buffer.
  const bool overSplat = splat && groundCopied_ && !depthPlane(params);
  const gpu::GraphicsProgram& program = overSplat ? jointsOverSplat_ : joints_;
  for (size_t c = 0; c < chunks.size(); ++c) {
    const JointChunk& chunk = chunks[c];
    gpu::Binding bindings[] = {
        gpu::storageBinding(gpu_types::kRenderBindingJoints, *params.joints,
                            chunk.firstCharacter * perCharacter,
                            chunk.characterCount * perCharacter),
        gpu::uniformBinding(gpu_types::kRenderBindingFrame, uniforms),
        gpu::storageBinding(gpu_types::kRenderBindingNearList, nearList_),
        gpu::storageBinding(gpu_types::kRenderBindingMasks,
                            params.masks ? *params.masks : noMasks_),
        gpu::storageBinding(gpu_types::kRenderBindingPlacement, *cached.placement),
        gpu::storageBinding(gpu_types::kRenderBindingMotion, *cached.motion),
        gpu::storageBinding(gpu_types::kRenderBindingPoseSource, *cached.poseSource),
        gpu::storageBinding(gpu_types::kRenderBindingCacheData, *cached.cacheData),
        gpu::storageBinding(gpu_types::kRenderBindingGroups,
                            params.groups ? *params.groups : noMasks_),
        gpu::uniformBinding(gpu_types::kRenderBindingLodLevels, *lodLevels, 0,
                            sizeof(gpu_types::CoverageParts)),
        gpu::storageBinding(gpu_types::kRenderBindingVisibility,
                            overSplat ? visibility_ : noMasks_)};
    push.firstCharacter = chunk.firstCharacter;
    push.listBase = chunk.firstCharacter * params.jointCount;
    program.bind(cmd, std::span(bindings, std::size(bindings) - (overSplat ? 0 : 1)), &push,
                 sizeof(push));
    if (splat) {
      vkCmdDrawIndirect(cmd, draws_.get(), c * 16, 1, 16);
    } else {
      vkCmdDraw(cmd, chunk.characterCount * params.jointCount, 1, 0, 0);
    }
  }
}

void CrowdRenderer::endDraw(VkCommandBuffer cmd, const FrameTargets& target) {
  if (!pendingGroundKey_.empty()) groundKey_ = std::exchange(pendingGroundKey_, {});
  passTimer_->mark(cmd, "after-resolve");
  vkCmdEndRenderingKHR(cmd);
  passTimer_->mark(cmd, "end-pass");
  const VkImageLayout finalLayout = target.finalLayout;

  // TRANSFER_SRC: a copy reads it next; GENERAL: the host reads it in place (a host-mapped
  // offscreen target); otherwise presentation or a later pass of the caller's.
  VkAccessFlags dstAccess = 0;
  VkPipelineStageFlags dstStage = VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT;
  if (finalLayout == VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL) {
    dstAccess = VK_ACCESS_TRANSFER_READ_BIT;
    dstStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
  } else if (finalLayout == VK_IMAGE_LAYOUT_GENERAL) {
    dstAccess = VK_ACCESS_HOST_READ_BIT;
    dstStage = VK_PIPELINE_STAGE_HOST_BIT;
  }
  gpu::transitionImage(cmd, target.color, VK_IMAGE_ASPECT_COLOR_BIT,
                       VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, finalLayout,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, dstStage, dstAccess);
}

void CrowdRenderer::record(VkCommandBuffer cmd, const FrameTargets& target,
                           const DrawParams& params, uint32_t frameSlot) {
  recordSplat(cmd, target, params, frameSlot);
  beginDraw(cmd, target, params, frameSlot);
  endDraw(cmd, target);
}

}  // namespace throng::render
