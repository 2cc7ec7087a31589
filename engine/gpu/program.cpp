#include "gpu/program.h"

#include <algorithm>

#include "core/error.h"
#include "gpu/limits.h"
#include "gpu/vk_check.h"
#include "shaders/embedded.h"

namespace throng::gpu {

Binding storageBinding(uint32_t slot, const Buffer& buffer, VkDeviceSize offset,
                       VkDeviceSize range) {
  Binding b;
  b.slot = slot;
  b.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  b.buffer = {buffer.get(), offset, range};
  b.bufferSize = buffer.size();
  return b;
}

Binding uniformBinding(uint32_t slot, const Buffer& buffer, VkDeviceSize offset,
                       VkDeviceSize range) {
  Binding b = storageBinding(slot, buffer, offset, range);
  b.type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  return b;
}

Binding sampledImageBinding(uint32_t slot, VkImageView view, VkSampler sampler) {
  Binding b;
  b.slot = slot;
  b.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  b.image = {sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  return b;
}

Binding uniformTexelBinding(uint32_t slot, VkBufferView view) {
  Binding b;
  b.slot = slot;
  b.type = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
  b.texelView = view;
  return b;
}

Handle<VkShaderModule> makeShaderModule(const Context& context, std::span<const uint32_t> words) {
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = words.size_bytes();
  info.pCode = words.data();
  VkDevice device = context.device();
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
  return Handle<VkShaderModule>(
      module, [device](VkShaderModule m) { vkDestroyShaderModule(device, m, nullptr); });
}

PipelineLayout makePipelineLayout(const Context& context, std::span<const ShaderReflection> shaders,
                                  const std::string& name) {
  PipelineLayout out;
  out.maxStorageBufferRange = context.info().maxStorageBufferRange;
  out.maxUniformBufferRange = context.info().maxUniformBufferRange;
  out.minStorageBufferOffsetAlignment = context.info().minStorageBufferOffsetAlignment;
  out.minUniformBufferOffsetAlignment = context.info().minUniformBufferOffsetAlignment;
  out.deviceName = context.info().name;
  for (const ShaderReflection& s : shaders) {
    out.stages |= s.stage;
    out.pushConstantSize = std::max(out.pushConstantSize, s.pushConstantSize);
    for (const ReflectedBinding& b : s.bindings) {
      auto same = std::find_if(out.bindings.begin(), out.bindings.end(),
                               [&](const ReflectedBinding& o) { return o.binding == b.binding; });
      if (same == out.bindings.end()) {
        out.bindings.push_back(b);
      } else if (same->type != b.type) {
        fail(name, ": binding ", b.binding, " has different types in different stages");
      }
    }
  }
  std::vector<VkDescriptorSetLayoutBinding> vkBindings;
  for (const ReflectedBinding& b : out.bindings)
    vkBindings.push_back({b.binding, b.type, 1, out.stages, nullptr});
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  setInfo.bindingCount = static_cast<uint32_t>(vkBindings.size());
  setInfo.pBindings = vkBindings.data();
  VkDevice device = context.device();
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VK_CHECK(vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout));
  out.setLayout = Handle<VkDescriptorSetLayout>(setLayout, [device](VkDescriptorSetLayout l) {
    vkDestroyDescriptorSetLayout(device, l, nullptr);
  });

  checkLimit(context, name + "'s push constants", "maxPushConstantsSize", out.pushConstantSize,
             context.info().maxPushConstantsSize);
  VkPushConstantRange range{out.stages, 0, out.pushConstantSize};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout;
  layoutInfo.pushConstantRangeCount = out.pushConstantSize > 0 ? 1 : 0;
  layoutInfo.pPushConstantRanges = &range;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout));
  out.layout = Handle<VkPipelineLayout>(
      layout, [device](VkPipelineLayout l) { vkDestroyPipelineLayout(device, l, nullptr); });
  return out;
}

namespace {
// The range a buffer binding covers, against the device's limit for its descriptor type
// (VUID-VkWriteDescriptorSet-descriptorType-00332/00333).
void checkBufferRange(const PipelineLayout& layout, const Binding& given, VkDescriptorType type,
                      const std::string& name) {
  const VkDescriptorBufferInfo& b = given.buffer;
  VkDeviceSize range = b.range;
  if (range == VK_WHOLE_SIZE) {
    if (given.bufferSize == 0) return;  // a raw VkBuffer of unknown size
    if (b.offset >= given.bufferSize)
      fail(name, ": binding ", given.slot, " starts at ", b.offset, ", past its buffer of ",
           given.bufferSize, " bytes");
    range = given.bufferSize - b.offset;
  } else if (given.bufferSize > 0 && b.offset + range > given.bufferSize) {
    fail(name, ": binding ", given.slot, " range ", b.offset, "+", range,
         " overflows its buffer of ", given.bufferSize, " bytes");
  }
  const bool storage = type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const uint64_t alignment =
      storage ? layout.minStorageBufferOffsetAlignment : layout.minUniformBufferOffsetAlignment;
  if (alignment > 1 && b.offset % alignment != 0)
    fail(name, ": binding ", given.slot, " starts at byte ", b.offset, ", not a multiple of ",
         layout.deviceName, "'s ",
         storage ? "minStorageBufferOffsetAlignment" : "minUniformBufferOffsetAlignment", " of ",
         alignment);
  const uint64_t limit = storage ? layout.maxStorageBufferRange : layout.maxUniformBufferRange;
  if (range > limit)
    throw LimitError(concat(name, " binding ", given.slot),
                     storage ? "maxStorageBufferRange" : "maxUniformBufferRange", range, limit,
                     "bytes", layout.deviceName);
}
}  // namespace

void pushBindings(VkCommandBuffer cmd, VkPipelineBindPoint bindPoint, const PipelineLayout& layout,
                  std::span<const Binding> bindings, const std::string& name) {
  std::vector<VkWriteDescriptorSet> writes;
  writes.reserve(layout.bindings.size());
  for (const ReflectedBinding& declared : layout.bindings) {
    auto given = std::find_if(bindings.begin(), bindings.end(),
                              [&](const Binding& b) { return b.slot == declared.binding; });
    if (given == bindings.end()) fail(name, ": binding ", declared.binding, " was not provided");
    if (given->type != declared.type)
      fail(name, ": binding ", declared.binding, " expects descriptor type ", declared.type,
           ", got ", given->type);
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstBinding = declared.binding;
    write.descriptorCount = 1;
    write.descriptorType = declared.type;
    if (declared.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER ||
        declared.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) {
      if (given->buffer.buffer == VK_NULL_HANDLE)
        fail(name, ": binding ", declared.binding, " has a null buffer");
      checkBufferRange(layout, *given, declared.type, name);
      write.pBufferInfo = &given->buffer;
    } else if (declared.type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER ||
               declared.type == VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER) {
      if (given->texelView == VK_NULL_HANDLE)
        fail(name, ": binding ", declared.binding, " has a null buffer view");
      write.pTexelBufferView = &given->texelView;
    } else {
      write.pImageInfo = &given->image;
    }
    writes.push_back(write);
  }
  if (bindings.size() != layout.bindings.size())
    fail(name, ": ", bindings.size(), " bindings given, shader declares ", layout.bindings.size());
  vkCmdPushDescriptorSetKHR(cmd, bindPoint, layout.layout, 0, static_cast<uint32_t>(writes.size()),
                            writes.data());
}

ComputeProgram::ComputeProgram(const Context& context, const std::string& shaderFile,
                               std::span<const uint32_t> specialization)
    : name_(shaderFile), maxGroupsX_(context.info().maxComputeWorkGroupCount[0]) {
  std::span<const uint32_t> words = shaders::embeddedSpirv(shaderFile);
  if (words.empty()) fail("shader ", shaderFile, " is not embedded in this build");
  reflection_ = reflectSpirv(words, shaderFile);
  if (reflection_.stage != VK_SHADER_STAGE_COMPUTE_BIT) fail(shaderFile, ": not a compute shader");
  layout_ = makePipelineLayout(context, std::span(&reflection_, 1), shaderFile);
  Handle<VkShaderModule> module = makeShaderModule(context, words);

  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  std::vector<VkSpecializationMapEntry> entries;
  for (uint32_t i = 0; i < specialization.size(); ++i)
    entries.push_back({i, static_cast<uint32_t>(i * sizeof(uint32_t)), sizeof(uint32_t)});
  VkSpecializationInfo specInfo{static_cast<uint32_t>(entries.size()), entries.data(),
                                specialization.size_bytes(), specialization.data()};
  if (!specialization.empty()) info.stage.pSpecializationInfo = &specInfo;
  info.layout = layout_.layout;
  VkDevice device = context.device();
  VkPipeline pipeline = VK_NULL_HANDLE;
  VK_CHECK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
  pipeline_ = Handle<VkPipeline>(pipeline,
                                 [device](VkPipeline p) { vkDestroyPipeline(device, p, nullptr); });
}

namespace {
void bindForDispatch(VkCommandBuffer cmd, const ComputeProgram& program,
                     std::span<const Binding> bindings, const void* pushConstants,
                     size_t pushSize) {
  const std::string& name = program.name();
  if (pushSize != program.layout().pushConstantSize)
    fail(name, ": push constants of ", pushSize, " bytes given, shader declares ",
         program.layout().pushConstantSize);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.pipeline());
  pushBindings(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, program.layout(), bindings, name);
  if (pushSize > 0)
    vkCmdPushConstants(cmd, program.layout().layout, program.layout().stages, 0,
                       static_cast<uint32_t>(pushSize), pushConstants);
}
}  // namespace

void dispatchIndirect(VkCommandBuffer cmd, const ComputeProgram& program,
                      std::span<const Binding> bindings, const void* pushConstants, size_t pushSize,
                      const Buffer& args, VkDeviceSize offset) {
  if (offset + 12 > args.size())
    fail(program.name(), ": indirect arguments at ", offset, " overflow their buffer");
  bindForDispatch(cmd, program, bindings, pushConstants, pushSize);
  vkCmdDispatchIndirect(cmd, args.get(), offset);
}

void dispatch(VkCommandBuffer cmd, const ComputeProgram& program, std::span<const Binding> bindings,
              const void* pushConstants, size_t pushSize, uint32_t threadCount) {
  const std::string& name = program.name();
  if (pushSize != program.layout().pushConstantSize)
    fail(name, ": push constants of ", pushSize, " bytes given, shader declares ",
         program.layout().pushConstantSize);
  if (threadCount == 0) return;
  const uint32_t groups = static_cast<uint32_t>((uint64_t(threadCount) + program.localSizeX() - 1) /
                                                program.localSizeX());
  if (groups > program.maxGroupsX())
    throw LimitError(concat(name, " dispatch of ", threadCount, " threads"),
                     "maxComputeWorkGroupCount[0]", groups, program.maxGroupsX(), "workgroups",
                     program.layout().deviceName);
  bindForDispatch(cmd, program, bindings, pushConstants, pushSize);
  vkCmdDispatch(cmd, groups, 1, 1);
}

}  // namespace throng::gpu
