#pragma once
#include <volk.h>

namespace throng::gpu {
// Throws Error "vkCall failed with VK_ERROR_... at file:line" for any non-success result.
void checkVk(VkResult result, const char* call, const char* file, int line);
const char* vkResultName(VkResult result);
}  // namespace throng::gpu

// Checked in every build type: Vulkan failures are reported, never ignored.
#define VK_CHECK(call) ::throng::gpu::checkVk((call), #call, __FILE__, __LINE__)
