#include "gpu/context.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/error.h"
#include "core/log.h"
#include "core/text.h"
#include "gpu/limits.h"
#include "gpu/vk_check.h"

namespace throng::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user) {
  if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
  static_cast<ValidationLog*>(user)->add(data->pMessageIdName);
  std::fprintf(stderr, "vulkan validation: %s\n", data->pMessage);
  return VK_FALSE;
}

bool envFlag(const char* name) {
  const char* v = std::getenv(name);
  return v && *v && std::strcmp(v, "0") != 0;
}

bool layerAvailable(const char* name) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
  std::vector<VkLayerProperties> layers(count);
  VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
    return std::strcmp(l.layerName, name) == 0;
  });
}

int typeRank(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 3;
    default:
      return 4;
  }
}

struct Candidate {
  VkPhysicalDevice device;
  VkPhysicalDeviceProperties properties;
  VkPhysicalDeviceDriverProperties driver;
  VkPhysicalDeviceMaintenance3Properties maintenance3;
};

// The instance functions device enumeration needs: volk's for a context's own instance, the
// temporary instance's own for listDevices().
struct InstanceFunctions {
  PFN_vkEnumeratePhysicalDevices enumeratePhysicalDevices;
  PFN_vkGetPhysicalDeviceProperties2 getPhysicalDeviceProperties2;
};

std::vector<Candidate> enumerateCandidates(VkInstance instance, const InstanceFunctions& vk) {
  uint32_t count = 0;
  VK_CHECK(vk.enumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vk.enumeratePhysicalDevices(instance, &count, devices.data()));
  std::vector<Candidate> result;
  for (VkPhysicalDevice d : devices) {
    Candidate c{d,
                {},
                {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES},
                {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES}};
    c.driver.pNext = &c.maintenance3;
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &c.driver};
    vk.getPhysicalDeviceProperties2(d, &props);
    c.properties = props.properties;
    if (c.properties.apiVersion < VK_API_VERSION_1_2) continue;
    result.push_back(c);
  }
  return result;
}

const Candidate& chooseDevice(const std::vector<Candidate>& candidates, const std::string& wanted) {
  if (candidates.empty())
    fail("no Vulkan 1.2 device found (install mesa-vulkan-drivers for lavapipe)");
  if (!wanted.empty()) {
    char* end = nullptr;
    long index = std::strtol(wanted.c_str(), &end, 10);
    if (end && *end == '\0') {
      if (index < 0 || index >= static_cast<long>(candidates.size()))
        fail("device index ", wanted, " out of range: ", candidates.size(), " device(s) available");
      return candidates[index];
    }
    for (const Candidate& c : candidates) {
      if (toLower(c.properties.deviceName).find(toLower(wanted)) != std::string::npos) return c;
    }
    std::string names;
    for (const Candidate& c : candidates) names += concat("\n  ", c.properties.deviceName);
    fail("no Vulkan device matches '", wanted, "'; available:", names);
  }
  return *std::min_element(
      candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
        return typeRank(a.properties.deviceType) < typeRank(b.properties.deviceType);
      });
}

void loadVolk() {
  static bool loaded = false;
  if (loaded) return;
  if (volkInitialize() != VK_SUCCESS) fail("Vulkan loader not found (install libvulkan1)");
  loaded = true;
}

bool layerHasExtension(const char* layer, const char* extension) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateInstanceExtensionProperties(layer, &count, nullptr));
  std::vector<VkExtensionProperties> extensions(count);
  VK_CHECK(vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()));
  return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, extension) == 0;
  });
}

bool deviceHasExtension(VkPhysicalDevice device, const char* extension) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> extensions(count);
  VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()));
  return std::any_of(extensions.begin(), extensions.end(), [&](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, extension) == 0;
  });
}

// The subgroup size and the operations compute shaders' subgroups support (none when compute
// shaders have no subgroup operations).
void readSubgroups(VkPhysicalDevice device, DeviceInfo& info) {
  VkPhysicalDeviceSubgroupProperties subgroup{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &subgroup};
  vkGetPhysicalDeviceProperties2(device, &properties);
  info.subgroupSize = subgroup.subgroupSize;
  info.computeSubgroupOperations = (subgroup.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) != 0
                                       ? subgroup.supportedOperations
                                       : 0;
}

// The largest VkBuffer, where the device reports it (VK_KHR_maintenance4); 0 otherwise.
uint64_t maxBufferSize(VkPhysicalDevice device) {
  if (!deviceHasExtension(device, VK_KHR_MAINTENANCE_4_EXTENSION_NAME)) return 0;
  VkPhysicalDeviceMaintenance4PropertiesKHR maintenance4{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_4_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &maintenance4};
  vkGetPhysicalDeviceProperties2(device, &props);
  return maintenance4.maxBufferSize;
}

template <typename Pfn>
Pfn instanceFunction(VkInstance instance, const char* name) {
  auto function = reinterpret_cast<Pfn>(vkGetInstanceProcAddr(instance, name));
  if (!function) fail("the Vulkan loader has no ", name);
  return function;
}

}  // namespace

void ValidationLog::add(const char* id) {
  count_.fetch_add(1);
  std::lock_guard<std::mutex> lock(mutex_);
  if (ids_.size() < kKeptIds) ids_.emplace_back(id ? id : "");
}

std::vector<std::string> ValidationLog::ids() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return ids_;
}

Context::Context(const ContextOptions& options)
    : validationLog_(std::make_unique<ValidationLog>()) {
  loadVolk();
  try {
    createInstance(options);
    choosePhysicalDevice(options);
    createDevice(options);
  } catch (...) {
    destroy();  // a failed constructor runs no destructor
    throw;
  }
  if (!options.quiet) {
    logInfo(concat("vulkan device: ", info_.name, " (driver ", info_.driver, ")",
                   validation_ ? (syncValidation_ ? ", validation on (with synchronization)"
                                                  : ", validation on")
                               : ""));
  }
}

void Context::createInstance(const ContextOptions& options) {
  validation_ = options.validation || envFlag("THRONG_VALIDATION");
  if (validation_ && !layerAvailable(kValidationLayer))
    fail("validation requested but ", kValidationLayer,
         " is not installed (vulkan-validationlayers)");
  const char* syncEnv = std::getenv("THRONG_SYNC_VALIDATION");
  syncValidation_ = validation_ && options.syncValidation &&
                    !(syncEnv && std::strcmp(syncEnv, "0") == 0) &&
                    layerHasExtension(kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);

  std::vector<const char*> extensions;
  for (const std::string& e : options.instanceExtensions) extensions.push_back(e.c_str());
  if (validation_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (syncValidation_) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "throng";
  app.pEngineName = "throng";
  app.apiVersion = VK_API_VERSION_1_2;
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{
      VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                                  VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = onValidationMessage;
  messengerInfo.pUserData = validationLog_.get();
  // The installed layer ignores VK_KHRONOS_VALIDATION_VALIDATE_SYNC; the feature struct works.
  const VkValidationFeatureEnableEXT syncFeature =
      VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = &syncFeature;
  if (syncValidation_) messengerInfo.pNext = &features;

  VkInstanceCreateInfo instanceInfo{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  instanceInfo.pApplicationInfo = &app;
  instanceInfo.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  instanceInfo.ppEnabledExtensionNames = extensions.data();
  if (validation_) {
    instanceInfo.enabledLayerCount = 1;
    instanceInfo.ppEnabledLayerNames = &kValidationLayer;
    instanceInfo.pNext = &messengerInfo;  // also catches instance creation messages
  }
  VK_CHECK(vkCreateInstance(&instanceInfo, nullptr, &instance_));
  // Instance and device functions through the loader's trampolines, which dispatch on the
  // handle: correct for every live context, unlike one device's direct pointers.
  volkLoadInstance(instance_);
  if (validation_) {
    auto create = instanceFunction<PFN_vkCreateDebugUtilsMessengerEXT>(
        instance_, "vkCreateDebugUtilsMessengerEXT");
    destroyMessenger_ = instanceFunction<PFN_vkDestroyDebugUtilsMessengerEXT>(
        instance_, "vkDestroyDebugUtilsMessengerEXT");
    messengerInfo.pNext = nullptr;
    VK_CHECK(create(instance_, &messengerInfo, nullptr, &messenger_));
  }
}

void Context::choosePhysicalDevice(const ContextOptions& options) {
  std::string wanted = options.device;
  if (wanted.empty() && std::getenv("THRONG_DEVICE")) wanted = std::getenv("THRONG_DEVICE");
  std::vector<Candidate> candidates =
      enumerateCandidates(instance_, {vkEnumeratePhysicalDevices, vkGetPhysicalDeviceProperties2});
  const Candidate& chosen = chooseDevice(candidates, wanted);
  physical_ = chosen.device;
  const VkPhysicalDeviceLimits& limits = chosen.properties.limits;
  info_.name = chosen.properties.deviceName;
  info_.driver = concat(chosen.driver.driverName, " ", chosen.driver.driverInfo);
  info_.type = chosen.properties.deviceType;
  info_.timestampPeriodNs = limits.timestampPeriod;
  info_.maxStorageBufferRange = limits.maxStorageBufferRange;
  info_.maxPushConstantsSize = limits.maxPushConstantsSize;
  info_.maxUniformBufferRange = limits.maxUniformBufferRange;
  info_.maxTexelBufferElements = limits.maxTexelBufferElements;
  info_.minStorageBufferOffsetAlignment = limits.minStorageBufferOffsetAlignment;
  info_.minUniformBufferOffsetAlignment = limits.minUniformBufferOffsetAlignment;
  info_.maxImageDimension2D = limits.maxImageDimension2D;
  info_.maxFramebufferWidth = limits.maxFramebufferWidth;
  info_.maxFramebufferHeight = limits.maxFramebufferHeight;
  for (int i = 0; i < 3; ++i)
    info_.maxComputeWorkGroupCount[i] = limits.maxComputeWorkGroupCount[i];
  info_.maxMemoryAllocationSize = chosen.maintenance3.maxMemoryAllocationSize;
  info_.maxBufferSize = maxBufferSize(physical_);
  readSubgroups(physical_, info_);
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  for (uint32_t h = 0; h < memory_.memoryHeapCount; ++h)
    if (memory_.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
      info_.deviceLocalBytes =
          std::max<uint64_t>(info_.deviceLocalBytes, memory_.memoryHeaps[h].size);
  VkPhysicalDeviceVulkan12Features supported12{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
  VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &supported12};
  vkGetPhysicalDeviceFeatures2(physical_, &supported);
  info_.int64Atomics = supported.features.shaderInt64 && supported12.shaderBufferInt64Atomics;

  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount, families.data());
  queueFamily_ = UINT32_MAX;
  for (uint32_t i = 0; i < familyCount; ++i) {
    VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if ((families[i].queueFlags & need) == need && families[i].timestampValidBits > 0) {
      queueFamily_ = i;
      break;
    }
  }
  if (queueFamily_ == UINT32_MAX)
    fail(info_.name, ": no queue family with graphics, compute and timestamps");
}

void Context::createDevice(const ContextOptions& options) {
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  std::vector<const char*> deviceExtensions{VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME,
                                            VK_KHR_DYNAMIC_RENDERING_EXTENSION_NAME};
  if (options.swapchain) deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

  VkPhysicalDeviceDynamicRenderingFeaturesKHR dynamicRendering{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DYNAMIC_RENDERING_FEATURES_KHR};
  dynamicRendering.dynamicRendering = VK_TRUE;
  VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                              &dynamicRendering};
  features12.hostQueryReset = VK_TRUE;
  features12.shaderBufferInt64Atomics = info_.int64Atomics ? VK_TRUE : VK_FALSE;
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &features12};
  features.features.multiDrawIndirect = VK_TRUE;
  features.features.drawIndirectFirstInstance = VK_TRUE;
  features.features.largePoints = VK_TRUE;
  features.features.shaderInt64 = info_.int64Atomics ? VK_TRUE : VK_FALSE;

  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  deviceInfo.enabledExtensionCount = static_cast<uint32_t>(deviceExtensions.size());
  deviceInfo.ppEnabledExtensionNames = deviceExtensions.data();
  VK_CHECK(vkCreateDevice(physical_, &deviceInfo, nullptr, &device_));
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
}

void Context::destroy() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (messenger_) destroyMessenger_(instance_, messenger_, nullptr);
  messenger_ = VK_NULL_HANDLE;
  if (instance_) vkDestroyInstance(instance_, nullptr);
  instance_ = VK_NULL_HANDLE;
}

Context::~Context() {
  destroy();
}

uint32_t Context::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const {
  for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if ((typeBits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & wanted) == wanted)
      return i;
  }
  fail("no Vulkan memory type with flags ", wanted, " for type bits ", typeBits, " on ",
       info_.name);
}

Handle<VkDeviceMemory> Context::allocateMemory(const VkMemoryRequirements& requirements,
                                               VkMemoryPropertyFlags wanted,
                                               const std::string& what) const {
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = requirements.size;
  alloc.memoryTypeIndex = findMemoryType(requirements.memoryTypeBits, wanted);
  const uint32_t heap = memory_.memoryTypes[alloc.memoryTypeIndex].heapIndex;
  checkLimit(*this, what, "maxMemoryAllocationSize", requirements.size,
             info_.maxMemoryAllocationSize);
  checkLimit(*this, what, concat("memory heap ", heap, " size"), requirements.size,
             memory_.memoryHeaps[heap].size);
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkResult result = vkAllocateMemory(device_, &alloc, nullptr, &memory);
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    throw LimitError(concat(what, " (", vkResultName(result), ")"),
                     concat("free memory in heap ", heap), requirements.size,
                     memory_.memoryHeaps[heap].size, "bytes", info_.name);
  VK_CHECK(result);
  VkDevice device = device_;
  return Handle<VkDeviceMemory>(memory,
                                [device](VkDeviceMemory m) { vkFreeMemory(device, m, nullptr); });
}

void Context::waitIdle() const {
  VK_CHECK(vkDeviceWaitIdle(device_));
}

std::vector<std::string> listDevices() {
  loadVolk();
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  VkInstance instance = VK_NULL_HANDLE;
  VK_CHECK(vkCreateInstance(&info, nullptr, &instance));
  // This instance's entry points, not volk's globals: loading them would replace the pointers
  // every live context uses (a null vkDestroyDebugUtilsMessengerEXT among them).
  auto destroyInstance = instanceFunction<PFN_vkDestroyInstance>(instance, "vkDestroyInstance");
  std::vector<std::string> names;
  try {
    InstanceFunctions functions{
        instanceFunction<PFN_vkEnumeratePhysicalDevices>(instance, "vkEnumeratePhysicalDevices"),
        instanceFunction<PFN_vkGetPhysicalDeviceProperties2>(instance,
                                                             "vkGetPhysicalDeviceProperties2")};
    int index = 0;
    for (const Candidate& c : enumerateCandidates(instance, functions))
      names.push_back(
          concat(index++, ": ", c.properties.deviceName, " (", c.driver.driverName, ")"));
  } catch (...) {
    destroyInstance(instance, nullptr);
    throw;
  }
  destroyInstance(instance, nullptr);
  return names;
}

}  // namespace throng::gpu
