#pragma once
// Command pools, one-shot submission and the barriers the passes use.
#include <functional>

#include "gpu/context.h"
#include "gpu/handle.h"

namespace throng::gpu {

class CommandPool {
 public:
  explicit CommandPool(const Context& context);
  VkCommandBuffer allocate() const;
  VkCommandPool get() const { return pool_; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  Handle<VkCommandPool> pool_;
};

class Fence {
 public:
  Fence(const Context& context, bool signaled = false);
  VkFence get() const { return fence_; }
  void wait() const;
  void reset() const;

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  Handle<VkFence> fence_;
};

// Records `record` into a fresh command buffer, submits it and waits for completion.
void submitAndWait(const Context& context, const std::function<void(VkCommandBuffer)>& record);

void beginCommands(VkCommandBuffer cmd);
void endCommands(VkCommandBuffer cmd);
void submit(const Context& context, VkCommandBuffer cmd, VkFence fence);

// Makes compute/transfer writes visible to later compute, indirect, vertex and transfer reads.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkPipelineStageFlags dst);
void computeToComputeBarrier(VkCommandBuffer cmd);

}  // namespace throng::gpu
