#pragma once
// Buffers: one allocation each (crowd-sized buffers are few and large). Host-visible buffers
// stay mapped; device-local ones are filled through a staging copy.
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "gpu/context.h"
#include "gpu/handle.h"

namespace throng::gpu {

enum class MemoryUse { DeviceLocal, HostVisible };

class Buffer {
 public:
  Buffer() = default;
  Buffer(const Context& context, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use);

  VkBuffer get() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  bool hostVisible() const { return mapped_ != nullptr; }
  void* mapped() const { return mapped_; }
  explicit operator bool() const { return static_cast<bool>(buffer_); }

  // A buffer over `size` bytes at `offset` of memory that something else owns (a host-mapped
  // image's texels, written by a pass as a storage buffer): an allocation of `memorySize` bytes
  // of memory type `memoryType`. Empty where the device binds no such buffer there. The memory's
  // owner outlives the buffer.
  static Buffer aliasing(const Context& context, VkDeviceMemory memory, uint32_t memoryType,
                         VkDeviceSize memorySize, VkDeviceSize offset, VkDeviceSize size,
                         VkBufferUsageFlags usage);

  template <typename T>
  std::span<T> hostSpan() const {
    return {static_cast<T*>(mapped_), static_cast<size_t>(size_ / sizeof(T))};
  }

 private:
  Handle<VkDeviceMemory> memory_;
  Handle<VkBuffer> buffer_;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
};

constexpr VkBufferUsageFlags kStorageUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                             VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                             VK_BUFFER_USAGE_TRANSFER_DST_BIT;

// A view of a whole buffer as texels of `format` (the buffer needs a texel-buffer usage bit).
// Throws when the buffer holds more texels than the device's maxTexelBufferElements.
Handle<VkBufferView> makeBufferView(const Context& context, const Buffer& buffer, VkFormat format);

// Copies bytes into a buffer (directly when mapped, else through a staging buffer).
void uploadBytes(const Context& context, const Buffer& dst, std::span<const uint8_t> bytes,
                 VkDeviceSize dstOffset = 0);
std::vector<uint8_t> readbackBytes(const Context& context, const Buffer& src, VkDeviceSize offset,
                                   VkDeviceSize size);

template <typename T>
Buffer makeStorageBuffer(const Context& context, std::span<const T> data,
                         MemoryUse use = MemoryUse::DeviceLocal,
                         VkBufferUsageFlags extraUsage = 0) {
  Buffer buffer(context, std::max<VkDeviceSize>(data.size_bytes(), 16), kStorageUsage | extraUsage,
                use);
  if (!data.empty())
    uploadBytes(context, buffer,
                {reinterpret_cast<const uint8_t*>(data.data()), data.size_bytes()});
  return buffer;
}

template <typename T>
std::vector<T> readback(const Context& context, const Buffer& src, size_t count, size_t first = 0) {
  std::vector<uint8_t> bytes = readbackBytes(context, src, first * sizeof(T), count * sizeof(T));
  std::vector<T> out(count);
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

}  // namespace throng::gpu
