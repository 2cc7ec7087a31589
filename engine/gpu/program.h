#pragma once
// A compute Program: SPIR-V + the layout reflected from it (push descriptors on set 0, one
// push-constant block) + the pipeline. `dispatch` binds, pushes and dispatches after checking
// that what the caller passes matches what the shader declares.
#include <span>
#include <string>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/context.h"
#include "gpu/handle.h"
#include "gpu/spirv_reflect.h"

namespace throng::gpu {

struct Binding {
  uint32_t slot = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  VkDescriptorBufferInfo buffer{};
  VkDescriptorImageInfo image{};
  VkBufferView texelView = VK_NULL_HANDLE;
  VkDeviceSize bufferSize = 0;  // the whole buffer's size: the range a VK_WHOLE_SIZE binding has
};

Binding storageBinding(uint32_t slot, const Buffer& buffer, VkDeviceSize offset = 0,
                       VkDeviceSize range = VK_WHOLE_SIZE);
Binding uniformBinding(uint32_t slot, const Buffer& buffer, VkDeviceSize offset = 0,
                       VkDeviceSize range = VK_WHOLE_SIZE);
Binding sampledImageBinding(uint32_t slot, VkImageView view, VkSampler sampler);
Binding uniformTexelBinding(uint32_t slot, VkBufferView view);

// Descriptor set layout (push descriptors) + pipeline layout for a set of stages.
struct PipelineLayout {
  Handle<VkDescriptorSetLayout> setLayout;
  Handle<VkPipelineLayout> layout;
  std::vector<ReflectedBinding> bindings;
  uint32_t pushConstantSize = 0;
  VkShaderStageFlags stages = 0;
  uint32_t maxStorageBufferRange = 0;  // the device's, checked for every binding pushed
  uint32_t maxUniformBufferRange = 0;
  uint64_t minStorageBufferOffsetAlignment = 1;  // binding offsets are multiples of these
  uint64_t minUniformBufferOffsetAlignment = 1;
  std::string deviceName;  // for LimitError's message
};
PipelineLayout makePipelineLayout(const Context& context, std::span<const ShaderReflection> shaders,
                                  const std::string& name);
Handle<VkShaderModule> makeShaderModule(const Context& context, std::span<const uint32_t> words);

// Pushes the descriptors after checking every declared binding is given with its type, and
// that each buffer range fits the device's maxStorageBufferRange / maxUniformBufferRange
// (LimitError otherwise) and starts at a multiple of its offset alignment.
void pushBindings(VkCommandBuffer cmd, VkPipelineBindPoint bindPoint, const PipelineLayout& layout,
                  std::span<const Binding> bindings, const std::string& name);

class ComputeProgram {
 public:
  ComputeProgram() = default;
  // `shaderFile` names an embedded shader (e.g. "synth_pose.comp"); `specialization[i]` is the
  // value of the shader's `layout(constant_id = i)` constant (32-bit each).
  ComputeProgram(const Context& context, const std::string& shaderFile,
                 std::span<const uint32_t> specialization = {});

  const std::string& name() const { return name_; }
  const ShaderReflection& reflection() const { return reflection_; }
  const PipelineLayout& layout() const { return layout_; }
  VkPipeline pipeline() const { return pipeline_; }
  uint32_t localSizeX() const { return reflection_.localSize[0]; }
  uint32_t maxGroupsX() const { return maxGroupsX_; }  // the device's maxComputeWorkGroupCount[0]

 private:
  std::string name_;
  ShaderReflection reflection_;
  PipelineLayout layout_;
  Handle<VkPipeline> pipeline_;
  uint32_t maxGroupsX_ = 0;
};

// Dispatches ceil(threadCount / localSizeX) groups. Throws when a binding is missing or of the
// wrong type, when the push-constant size differs from the shader's, and LimitError when the
// group count exceeds the device's maxComputeWorkGroupCount or a range its binding limit.
void dispatch(VkCommandBuffer cmd, const ComputeProgram& program, std::span<const Binding> bindings,
              const void* pushConstants, size_t pushSize, uint32_t threadCount);

// The same with the group count read from `args` (a VkDispatchIndirectCommand at `offset`).
void dispatchIndirect(VkCommandBuffer cmd, const ComputeProgram& program,
                      std::span<const Binding> bindings, const void* pushConstants, size_t pushSize,
                      const Buffer& args, VkDeviceSize offset);

template <typename Push>
void dispatch(VkCommandBuffer cmd, const ComputeProgram& program, std::span<const Binding> bindings,
              const Push& push, uint32_t threadCount) {
  dispatch(cmd, program, bindings, &push, sizeof(Push), threadCount);
}

}  // namespace throng::gpu
