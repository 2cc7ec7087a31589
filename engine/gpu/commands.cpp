#include "gpu/commands.h"

#include "gpu/vk_check.h"

namespace throng::gpu {

CommandPool::CommandPool(const Context& context) : device_(context.device()) {
  VkCommandPoolCreateInfo info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  info.queueFamilyIndex = context.queueFamily();
  VkCommandPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateCommandPool(device_, &info, nullptr, &pool));
  VkDevice device = device_;
  pool_ = Handle<VkCommandPool>(pool, [device](VkCommandPool p) { vkDestroyCommandPool(device, p, nullptr); });
}

VkCommandBuffer CommandPool::allocate() const {
  VkCommandBufferAllocateInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  info.commandPool = pool_;
  info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  info.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VK_CHECK(vkAllocateCommandBuffers(device_, &info, &cmd));
  return cmd;
}

Fence::Fence(const Context& context, bool signaled) : device_(context.device()) {
  VkFenceCreateInfo info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  if (signaled) info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
  VkFence fence = VK_NULL_HANDLE;
  VK_CHECK(vkCreateFence(device_, &info, nullptr, &fence));
  VkDevice device = device_;
  fence_ = Handle<VkFence>(fence, [device](VkFence f) { vkDestroyFence(device, f, nullptr); });
}

void Fence::wait() const {
  VkFence f = fence_;
  VK_CHECK(vkWaitForFences(device_, 1, &f, VK_TRUE, UINT64_MAX));
}
void Fence::reset() const {
  VkFence f = fence_;
  VK_CHECK(vkResetFences(device_, 1, &f));
}

void beginCommands(VkCommandBuffer cmd) {
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
}

void endCommands(VkCommandBuffer cmd) { VK_CHECK(vkEndCommandBuffer(cmd)); }

void submit(const Context& context, VkCommandBuffer cmd, VkFence fence) {
  VkSubmitInfo info{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  info.commandBufferCount = 1;
  info.pCommandBuffers = &cmd;
  VK_CHECK(vkQueueSubmit(context.queue(), 1, &info, fence));
}

void submitAndWait(const Context& context, const std::function<void(VkCommandBuffer)>& record) {
  CommandPool pool(context);
  VkCommandBuffer cmd = pool.allocate();
  beginCommands(cmd);
  record(cmd);
  endCommands(cmd);
  Fence fence(context);
  submit(context, cmd, fence.get());
  fence.wait();
}

namespace {
// The accesses a stage mask can perform, so barriers name exactly what the stages do.
VkAccessFlags accessesOf(VkPipelineStageFlags stages) {
  VkAccessFlags access = 0;
  if (stages & (VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT))
    access |= VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
  if (stages & VK_PIPELINE_STAGE_TRANSFER_BIT) access |= VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
  if (stages & VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT) access |= VK_ACCESS_INDIRECT_COMMAND_READ_BIT;
  if (stages & VK_PIPELINE_STAGE_HOST_BIT) access |= VK_ACCESS_HOST_READ_BIT;
  return access;
}
}  // namespace

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags src, VkPipelineStageFlags dst) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = accessesOf(src) & (VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
  barrier.dstAccessMask = accessesOf(dst);
  vkCmdPipelineBarrier(cmd, src, dst, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void computeToComputeBarrier(VkCommandBuffer cmd) {
  memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT);
}

}  // namespace throng::gpu
