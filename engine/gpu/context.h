#pragma once
// Instance, physical-device choice, logical device and the one compute+graphics queue.
// Headless by default; a presenter passes the instance extensions its surface needs.
#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "gpu/handle.h"

namespace throng::gpu {

struct ContextOptions {
  // Device by index or by case-insensitive name substring; empty: $THRONG_DEVICE, then the
  // best real GPU, then lavapipe.
  std::string device;
  // Khronos validation layer; also turned on by THRONG_VALIDATION=1.
  bool validation = false;
  std::vector<std::string> instanceExtensions;  // e.g. from glfwGetRequiredInstanceExtensions
  bool swapchain = false;                       // enable VK_KHR_swapchain on the device
  bool quiet = false;                           // do not print the chosen device
};

struct DeviceInfo {
  std::string name;
  std::string driver;
  VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
  float timestampPeriodNs = 1.0f;
  uint32_t maxStorageBufferRange = 0;
  uint32_t maxUniformBufferRange = 0;
  uint32_t maxTexelBufferElements = 0;
  bool int64Atomics = false;  // shaderInt64 + shaderBufferInt64Atomics (the joint splat needs them)
  uint64_t deviceLocalBytes = 0;  // the largest device-local heap (lavapipe: system memory)
  bool isCpu() const { return type == VK_PHYSICAL_DEVICE_TYPE_CPU; }
};

class Context {
 public:
  explicit Context(const ContextOptions& options = {});
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkDevice device() const { return device_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const DeviceInfo& info() const { return info_; }
  bool validationEnabled() const { return validation_; }

  // Validation warnings and errors seen so far (tests assert zero).
  uint32_t validationMessageCount() const { return validationMessages_->load(); }

  uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const;
  // One allocation of a memory type with `wanted` flags that satisfies `requirements`.
  Handle<VkDeviceMemory> allocateMemory(const VkMemoryRequirements& requirements,
                                        VkMemoryPropertyFlags wanted) const;
  void waitIdle() const;

 private:
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  DeviceInfo info_;
  bool validation_ = false;
  VkPhysicalDeviceMemoryProperties memory_{};
  std::unique_ptr<std::atomic<uint32_t>> validationMessages_;
};

// Names of the devices the loader reports, with their index (for --list-devices).
std::vector<std::string> listDevices();

}  // namespace throng::gpu
