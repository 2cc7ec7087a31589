#pragma once
// Reads what a pipeline layout needs straight from the SPIR-V words (bindings of set 0 with
// their descriptor types, push-constant block size, compute workgroup size), so that the C++
// side never restates a shader's interface by hand.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <volk.h>

namespace throng::gpu {

struct ReflectedBinding {
  uint32_t set = 0;
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
};

struct ShaderReflection {
  VkShaderStageFlagBits stage = VK_SHADER_STAGE_COMPUTE_BIT;
  std::vector<ReflectedBinding> bindings;  // sorted by binding
  uint32_t pushConstantSize = 0;
  uint32_t localSize[3] = {1, 1, 1};
};

// Throws Error naming `shaderName` when the words are not valid SPIR-V.
ShaderReflection reflectSpirv(std::span<const uint32_t> words, const std::string& shaderName);

}  // namespace throng::gpu
