#pragma once
// A graphics Program: vertex + fragment SPIR-V, reflected layout, and a pipeline for dynamic
// rendering into one colour and one depth attachment (no render pass objects).
#include <string>

#include "gpu/context.h"
#include "gpu/program.h"

namespace throng::gpu {

struct GraphicsPipelineDesc {
  std::string vertexShader;    // embedded file name, e.g. "joints.vert"
  std::string fragmentShader;
  VkFormat colorFormat = VK_FORMAT_R8G8B8A8_UNORM;
  VkFormat depthFormat = VK_FORMAT_D32_SFLOAT;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkCullModeFlags cullMode = VK_CULL_MODE_BACK_BIT;
  bool depthWrite = true;
  bool alphaBlend = false;
};

class GraphicsProgram {
 public:
  GraphicsProgram() = default;
  GraphicsProgram(const Context& context, const GraphicsPipelineDesc& desc);

  const std::string& name() const { return name_; }
  const PipelineLayout& layout() const { return layout_; }
  VkPipeline pipeline() const { return pipeline_; }

  // Binds the pipeline, pushes descriptors and push constants (sizes checked).
  void bind(VkCommandBuffer cmd, std::span<const Binding> bindings, const void* push, size_t pushSize) const;

 private:
  std::string name_;
  PipelineLayout layout_;
  Handle<VkPipeline> pipeline_;
};

}  // namespace throng::gpu
