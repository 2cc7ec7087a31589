#pragma once
// GPU timestamps: a query pool with named marks; durations between marks in milliseconds.
#include <string>
#include <vector>

#include "gpu/context.h"
#include "gpu/handle.h"

namespace throng::gpu {

class TimestampPool {
 public:
  TimestampPool(const Context& context, uint32_t capacity);
  // Resets the queries on the host (Vulkan 1.2 hostQueryReset); call before recording.
  void reset();
  // Writes a timestamp after all previous work; returns its index.
  uint32_t write(VkCommandBuffer cmd,
                 VkPipelineStageFlagBits stage = VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
  // After the work completed: milliseconds between marks `from` and `to`.
  std::vector<uint64_t> fetch() const;
  // Without waiting: the marks when all of them have been written (their work completed), else
  // nothing (a command buffer that was never submitted writes none).
  std::vector<uint64_t> fetchIfAvailable() const;
  double millisecondsBetween(const std::vector<uint64_t>& ticks, uint32_t from, uint32_t to) const;

 private:
  // The used marks' ticks with the given result flags (64-bit always).
  VkResult query(std::vector<uint64_t>& ticks, VkQueryResultFlags flags) const;
  VkDevice device_ = VK_NULL_HANDLE;
  Handle<VkQueryPool> pool_;
  uint32_t capacity_ = 0;
  uint32_t used_ = 0;
  float periodNs_ = 1.0f;
};

}  // namespace throng::gpu
