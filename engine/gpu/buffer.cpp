#include "gpu/buffer.h"

#include "core/error.h"
#include "gpu/commands.h"
#include "gpu/limits.h"
#include "gpu/vk_check.h"

namespace throng::gpu {

Buffer::Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use)
    : size_(size) {
  THRONG_CHECK(size > 0, "buffer size must be positive");
  VkDevice device = context.device();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (context.info().maxBufferSize > 0)
    checkLimit(context, "a buffer", "maxBufferSize", size, context.info().maxBufferSize);
  VkBuffer buffer = VK_NULL_HANDLE;
  VkResult created = vkCreateBuffer(device, &info, nullptr, &buffer);
  if (created == VK_ERROR_OUT_OF_DEVICE_MEMORY || created == VK_ERROR_OUT_OF_HOST_MEMORY)
    throw LimitError(concat("a buffer (", vkResultName(created), ")"), "device-local memory", size,
                     context.info().deviceLocalBytes, "bytes", context.info().name);
  VK_CHECK(created);
  buffer_ = Handle<VkBuffer>(buffer, [device](VkBuffer b) { vkDestroyBuffer(device, b, nullptr); });

  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device, buffer, &requirements);
  VkMemoryPropertyFlags flags =
      use == MemoryUse::HostVisible
          ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
          : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
  memory_ = context.allocateMemory(requirements, flags, "a buffer");
  VK_CHECK(vkBindBufferMemory(device, buffer, memory_, 0));
  if (use == MemoryUse::HostVisible)
    VK_CHECK(vkMapMemory(device, memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
}

Buffer Buffer::aliasing(const Context& context, VkDeviceMemory memory, uint32_t memoryType,
                        VkDeviceSize memorySize, VkDeviceSize offset, VkDeviceSize size,
                        VkBufferUsageFlags usage) {
  THRONG_CHECK(size > 0, "buffer size must be positive");
  const bool storage = (usage & VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) != 0;
  if (storage && size > context.info().maxStorageBufferRange) return Buffer();
  VkDevice device = context.device();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VkBuffer buffer = VK_NULL_HANDLE;
  VK_CHECK(vkCreateBuffer(device, &info, nullptr, &buffer));
  Buffer alias;
  alias.buffer_ =
      Handle<VkBuffer>(buffer, [device](VkBuffer b) { vkDestroyBuffer(device, b, nullptr); });
  VkMemoryRequirements requirements;
  vkGetBufferMemoryRequirements(device, buffer, &requirements);
  if ((requirements.memoryTypeBits & (1u << memoryType)) == 0 ||
      offset % requirements.alignment != 0 || offset > memorySize ||
      requirements.size > memorySize - offset)
    return Buffer();
  VK_CHECK(vkBindBufferMemory(device, buffer, memory, offset));
  alias.size_ = size;
  return alias;
}

namespace {
VkDeviceSize texelBytes(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_R32_SFLOAT:
      return 4;
    case VK_FORMAT_R32G32_UINT:
    case VK_FORMAT_R32G32_SFLOAT:
      return 8;
    case VK_FORMAT_R32G32B32A32_UINT:
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return 16;
    default:
      fail("makeBufferView: texel format ", int(format), " is not one this engine uses");
  }
}
}  // namespace

Handle<VkBufferView> makeBufferView(const Context& context, const Buffer& buffer, VkFormat format) {
  VkDevice device = context.device();
  const VkDeviceSize texels = buffer.size() / texelBytes(format);
  checkLimit(context, concat("a texel buffer view of ", buffer.size(), " bytes"),
             "maxTexelBufferElements", texels, context.info().maxTexelBufferElements, "texels");
  VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  info.buffer = buffer.get();
  info.format = format;
  info.offset = 0;
  info.range = VK_WHOLE_SIZE;
  VkBufferView view = VK_NULL_HANDLE;
  VK_CHECK(vkCreateBufferView(device, &info, nullptr, &view));
  return Handle<VkBufferView>(
      view, [device](VkBufferView v) { vkDestroyBufferView(device, v, nullptr); });
}

void uploadBytes(const Context& context, const Buffer& dst, std::span<const uint8_t> bytes,
                 VkDeviceSize dstOffset) {
  THRONG_CHECK(dstOffset + bytes.size() <= dst.size(), "upload of ", bytes.size(), " bytes at ",
               dstOffset, " overflows a buffer of ", dst.size());
  if (bytes.empty()) return;
  if (dst.hostVisible()) {
    std::memcpy(static_cast<uint8_t*>(dst.mapped()) + dstOffset, bytes.data(), bytes.size());
    return;
  }
  Buffer staging(context, bytes.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUse::HostVisible);
  std::memcpy(staging.mapped(), bytes.data(), bytes.size());
  submitAndWait(context, [&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, dstOffset, bytes.size()};
    vkCmdCopyBuffer(cmd, staging.get(), dst.get(), 1, &region);
  });
}

std::vector<uint8_t> readbackBytes(const Context& context, const Buffer& src, VkDeviceSize offset,
                                   VkDeviceSize size) {
  THRONG_CHECK(offset + size <= src.size(), "readback of ", size, " bytes at ", offset,
               " overflows a buffer of ", src.size());
  std::vector<uint8_t> out(size);
  if (size == 0) return out;
  if (src.hostVisible()) {
    std::memcpy(out.data(), static_cast<const uint8_t*>(src.mapped()) + offset, size);
    return out;
  }
  Buffer staging(context, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUse::HostVisible);
  submitAndWait(context, [&](VkCommandBuffer cmd) {
    VkBufferCopy region{offset, 0, size};
    vkCmdCopyBuffer(cmd, src.get(), staging.get(), 1, &region);
  });
  std::memcpy(out.data(), staging.mapped(), size);
  return out;
}

}  // namespace throng::gpu
