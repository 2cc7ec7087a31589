#include "gpu/vk_check.h"

#include "core/error.h"

namespace throng::gpu {

const char* vkResultName(VkResult result) {
  switch (result) {
#define THRONG_RESULT(name) \
  case name:                \
    return #name;
    THRONG_RESULT(VK_SUCCESS)
    THRONG_RESULT(VK_NOT_READY)
    THRONG_RESULT(VK_TIMEOUT)
    THRONG_RESULT(VK_INCOMPLETE)
    THRONG_RESULT(VK_SUBOPTIMAL_KHR)
    THRONG_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
    THRONG_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    THRONG_RESULT(VK_ERROR_INITIALIZATION_FAILED)
    THRONG_RESULT(VK_ERROR_DEVICE_LOST)
    THRONG_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
    THRONG_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
    THRONG_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
    THRONG_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
    THRONG_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
    THRONG_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
    THRONG_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
    THRONG_RESULT(VK_ERROR_SURFACE_LOST_KHR)
    THRONG_RESULT(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    THRONG_RESULT(VK_ERROR_OUT_OF_DATE_KHR)
#undef THRONG_RESULT
    default:
      return "VK_ERROR_(unknown)";
  }
}

void checkVk(VkResult result, const char* call, const char* file, int line) {
  if (result == VK_SUCCESS) return;
  fail(call, " failed with ", vkResultName(result), " (", static_cast<int>(result), ") at ", file,
       ":", line);
}

}  // namespace throng::gpu
