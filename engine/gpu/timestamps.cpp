#include "gpu/timestamps.h"

#include "core/error.h"
#include "gpu/vk_check.h"

namespace throng::gpu {

TimestampPool::TimestampPool(const Context& context, uint32_t capacity)
    : device_(context.device()), capacity_(capacity), periodNs_(context.info().timestampPeriodNs) {
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = capacity;
  VkQueryPool pool = VK_NULL_HANDLE;
  VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &pool));
  VkDevice device = device_;
  pool_ = Handle<VkQueryPool>(pool,
                              [device](VkQueryPool p) { vkDestroyQueryPool(device, p, nullptr); });
  reset();
}

void TimestampPool::reset() {
  vkResetQueryPool(device_, pool_, 0, capacity_);
  used_ = 0;
}

uint32_t TimestampPool::write(VkCommandBuffer cmd, VkPipelineStageFlagBits stage) {
  THRONG_CHECK(used_ < capacity_, "timestamp pool of ", capacity_, " queries is full");
  vkCmdWriteTimestamp(cmd, stage, pool_, used_);
  return used_++;
}

VkResult TimestampPool::query(std::vector<uint64_t>& ticks, VkQueryResultFlags flags) const {
  ticks.assign(used_, 0);
  if (used_ == 0) return VK_SUCCESS;
  return vkGetQueryPoolResults(device_, pool_, 0, used_, ticks.size() * sizeof(uint64_t),
                               ticks.data(), sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | flags);
}

std::vector<uint64_t> TimestampPool::fetch() const {
  std::vector<uint64_t> ticks;
  VK_CHECK(query(ticks, VK_QUERY_RESULT_WAIT_BIT));
  return ticks;
}

std::vector<uint64_t> TimestampPool::fetchIfAvailable() const {
  std::vector<uint64_t> ticks;
  const VkResult result = query(ticks, 0);
  if (result == VK_NOT_READY) return {};
  VK_CHECK(result);
  return ticks;
}

double TimestampPool::millisecondsBetween(const std::vector<uint64_t>& ticks, uint32_t from,
                                          uint32_t to) const {
  THRONG_CHECK(from < ticks.size() && to < ticks.size(), "timestamp index out of range");
  return static_cast<double>(ticks[to] - ticks[from]) * periodNs_ * 1e-6;
}

}  // namespace throng::gpu
