#include "gpu/image.h"

#include <cstring>

#include "core/error.h"
#include "gpu/buffer.h"
#include "gpu/commands.h"
#include "gpu/limits.h"
#include "gpu/vk_check.h"

namespace throng::gpu {

bool Image2D::hostMappable(const Context& context, VkFormat format, VkImageUsageFlags usage,
                           uint32_t width, uint32_t height) {
  VkImageFormatProperties properties{};
  if (vkGetPhysicalDeviceImageFormatProperties(context.physicalDevice(), format, VK_IMAGE_TYPE_2D,
                                               VK_IMAGE_TILING_LINEAR, usage, 0,
                                               &properties) != VK_SUCCESS)
    return false;
  return width <= properties.maxExtent.width && height <= properties.maxExtent.height;
}

Image2D::Image2D(const Context& context, uint32_t width, uint32_t height, VkFormat format,
                 VkImageUsageFlags usage, VkImageAspectFlags aspect, ImageMemory memory)
    : format_(format), width_(width), height_(height), aspect_(aspect) {
  const bool hostMapped = memory == ImageMemory::HostMapped;
  if (hostMapped && !hostMappable(context, format, usage, width, height))
    fail("a host-mapped ", width, "x", height, " image: no linear tiling for its format and usage");
  THRONG_CHECK(width > 0 && height > 0, "image size must be positive, got ", width, "x", height);
  const bool attachment = (usage & (VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                    VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT)) != 0;
  checkImageSize(context, concat("a ", width, "x", height, " image"), width, height, attachment);
  VkDevice device = context.device();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = hostMapped ? VK_IMAGE_TILING_LINEAR : VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VkImage image = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImage(device, &info, nullptr, &image));
  image_ = Handle<VkImage>(image, [device](VkImage i) { vkDestroyImage(device, i, nullptr); });

  VkMemoryRequirements requirements;
  vkGetImageMemoryRequirements(device, image, &requirements);
  const VkMemoryPropertyFlags wanted =
      hostMapped ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                 : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  memory_ =
      context.allocateMemory(requirements, wanted, concat("a ", width, "x", height, " image"));
  memoryType_ = context.findMemoryType(requirements.memoryTypeBits, wanted);
  memorySize_ = requirements.size;
  VK_CHECK(vkBindImageMemory(device, image, memory_, 0));
  if (hostMapped) {
    VK_CHECK(vkMapMemory(device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
    const VkImageSubresource subresource{aspect, 0, 0};
    VkSubresourceLayout layout{};
    vkGetImageSubresourceLayout(device, image, &subresource, &layout);
    mapped_ = static_cast<uint8_t*>(mapped_) + layout.offset;
    rowPitch_ = layout.rowPitch;
    texelOffset_ = layout.offset;
  }

  VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  viewInfo.image = image;
  viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
  viewInfo.format = format;
  viewInfo.subresourceRange = {aspect, 0, 1, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
  view_ = Handle<VkImageView>(view,
                              [device](VkImageView v) { vkDestroyImageView(device, v, nullptr); });
}

Buffer Image2D::texelBuffer(const Context& context, VkBufferUsageFlags usage) const {
  if (!mapped_) return Buffer();
  return Buffer::aliasing(context, memory_, memoryType_, memorySize_, texelOffset_,
                          rowPitch_ * height_, usage);
}

void transitionImage(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect,
                     VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                     VkAccessFlags srcAccess, VkPipelineStageFlags dstStage,
                     VkAccessFlags dstAccess) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {aspect, 0, 1, 0, 1};
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

void uploadImage(const Context& context, const Image2D& image, std::span<const uint8_t> texels) {
  Buffer staging(context, texels.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::HostVisible);
  std::memcpy(staging.mapped(), texels.data(), texels.size());
  submitAndWait(context, [&](VkCommandBuffer cmd) {
    transitionImage(cmd, image.get(), image.aspect(), VK_IMAGE_LAYOUT_UNDEFINED,
                    VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0,
                    VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {image.aspect(), 0, 0, 1};
    region.imageExtent = {image.width(), image.height(), 1};
    vkCmdCopyBufferToImage(cmd, staging.get(), image.get(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &region);
    transitionImage(cmd, image.get(), image.aspect(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                    VK_ACCESS_TRANSFER_WRITE_BIT,
                    VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT,
                    VK_ACCESS_SHADER_READ_BIT);
  });
}

Handle<VkSampler> makeNearestSampler(const Context& context) {
  VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  info.magFilter = VK_FILTER_NEAREST;
  info.minFilter = VK_FILTER_NEAREST;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  info.maxLod = 0.0f;
  VkDevice device = context.device();
  VkSampler sampler = VK_NULL_HANDLE;
  VK_CHECK(vkCreateSampler(device, &info, nullptr, &sampler));
  return Handle<VkSampler>(sampler,
                           [device](VkSampler s) { vkDestroySampler(device, s, nullptr); });
}

}  // namespace throng::gpu
