#pragma once
// Instance, physical-device choice, logical device and the one compute+graphics queue.
// Headless by default; a presenter passes the instance extensions its surface needs.
// Several contexts may live at once: Vulkan calls go through the loader's dispatch (volk's
// instance-level loading), so no context's function pointers depend on another's device.
#include <atomic>
#include <memory>
#include <mutex>
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
  // With validation: the layer's synchronization validation too (missing barriers are
  // reported as SYNC-HAZARD-* messages). THRONG_SYNC_VALIDATION=0 turns it off.
  bool syncValidation = true;
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
  uint64_t minStorageBufferOffsetAlignment = 1;
  uint64_t minUniformBufferOffsetAlignment = 1;
  uint32_t maxImageDimension2D = 0;
  uint32_t maxFramebufferWidth = 0;
  uint32_t maxFramebufferHeight = 0;
  uint32_t maxComputeWorkGroupCount[3] = {0, 0, 0};
  uint32_t maxPushConstantsSize = 128;   // bytes (the Vulkan minimum)
  uint64_t maxMemoryAllocationSize = 0;  // one vkAllocateMemory (Vulkan 1.1 maintenance3)
  uint64_t maxBufferSize = 0;            // one vkCreateBuffer (VK_KHR_maintenance4); 0: unknown
  bool int64Atomics = false;  // shaderInt64 + shaderBufferInt64Atomics (the joint splat needs them)
  uint32_t subgroupSize = 0;  // lanes per subgroup
  VkSubgroupFeatureFlags computeSubgroupOperations = 0;  // what compute shaders' subgroups can do
  uint64_t deviceLocalBytes = 0;  // the largest device-local heap (lavapipe: system memory)
  bool isCpu() const { return type == VK_PHYSICAL_DEVICE_TYPE_CPU; }
};

// What the validation layer reported: the count (tests assert zero) and the first messages'
// ids ("VUID-...", "SYNC-HAZARD-...") so that a test can expect a particular one.
class ValidationLog {
 public:
  void add(const char* id);
  uint32_t count() const { return count_.load(); }
  std::vector<std::string> ids() const;

 private:
  static constexpr size_t kKeptIds = 256;
  std::atomic<uint32_t> count_{0};
  mutable std::mutex mutex_;
  std::vector<std::string> ids_;
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
  bool syncValidationEnabled() const { return syncValidation_; }

  // Validation warnings and errors seen so far (tests assert zero).
  uint32_t validationMessageCount() const { return validationLog_->count(); }
  std::vector<std::string> validationMessageIds() const { return validationLog_->ids(); }

  uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const;
  // One allocation of a memory type with `wanted` flags that satisfies `requirements`. Throws
  // LimitError when it exceeds maxMemoryAllocationSize or the heap, or the driver is out of
  // memory; `what` names the allocation in that message.
  Handle<VkDeviceMemory> allocateMemory(const VkMemoryRequirements& requirements,
                                        VkMemoryPropertyFlags wanted,
                                        const std::string& what = "an allocation") const;
  void waitIdle() const;

 private:
  void createInstance(const ContextOptions& options);
  void choosePhysicalDevice(const ContextOptions& options);
  void createDevice(const ContextOptions& options);
  void destroy();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  // This instance's own entry point: another context may load volk's pointer without the
  // debug-utils extension.
  PFN_vkDestroyDebugUtilsMessengerEXT destroyMessenger_ = nullptr;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  DeviceInfo info_;
  bool validation_ = false;
  bool syncValidation_ = false;
  VkPhysicalDeviceMemoryProperties memory_{};
  std::unique_ptr<ValidationLog> validationLog_;
};

// Names of the devices the loader reports, with their index (for --list-devices). Uses a
// temporary instance of its own and leaves every context's function pointers as they were.
std::vector<std::string> listDevices();

}  // namespace throng::gpu
