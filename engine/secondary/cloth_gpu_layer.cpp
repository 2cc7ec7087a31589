#include "secondary/cloth_gpu_layer.h"

#include <algorithm>
#include <cstring>

#include "core/error.h"
#include "gpu/commands.h"

namespace throng::secondary {

namespace {
// Marks per frame: start, advanced, marked, decoded (compute hook), splat start and end, draw
// start and end.
constexpr uint32_t kMarks = 8;
constexpr uint32_t kNoMark = 0xFFFFFFFFu;
constexpr VkDeviceSize kCounterBytes = sizeof(gpu_types::ClothCounters);
constexpr VkDeviceSize kDrawBytes = kClothLevels * 20;  // VkDrawIndexedIndirectCommand per level
}  // namespace

ClothLayer::ClothLayer(const gpu::Context& context, const ClothDatabase& db,
                       const crowd::CrowdBuffers& crowd, VkFormat colorFormat, VkFormat depthFormat,
                       const ClothLayerOptions& options)
    : crowd_(&crowd),
      options_(options),
      programs_(context, colorFormat, depthFormat),
      cloth_(uploadCloth(context, db)),
      buffers_(makeClothCrowdBuffers(context, cloth_, crowd.count, options.fineBudgetBytes)) {
  for (uint32_t i = 0; i < render::kFramesInFlight; ++i) {
    // A uniform buffer for the mark and the draw, a storage buffer for the splat (its shader says
    // why).
    views_.emplace_back(context, sizeof(gpu_types::ClothView),
                        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                        gpu::MemoryUse::HostVisible);
    timestamps_.push_back(std::make_unique<gpu::TimestampPool>(context, kMarks));
    statsCopies_.emplace_back(context, kCounterBytes + kDrawBytes, gpu::kStorageUsage,
                              gpu::MemoryUse::HostVisible);
    std::memset(statsCopies_.back().mapped(), 0, kCounterBytes + kDrawBytes);
  }
  splatMarks_.assign(render::kFramesInFlight, kNoMark);
  drawMarks_.assign(render::kFramesInFlight, kNoMark);
  splatted_.assign(render::kFramesInFlight, false);
  frameNumbers_.assign(render::kFramesInFlight, 0);
}

void ClothLayer::recordCompute(VkCommandBuffer cmd, const render::Camera& camera, uint32_t width,
                               uint32_t height, uint32_t slot) {
  THRONG_CHECK(slot < render::kFramesInFlight, "frame slot ", slot, " out of range");
  gpu_types::ClothView view =
      makeClothView(camera, width, height, cloth_.lod, options_.lod, clothSplattable(cloth_));
  view.viewport.w = options_.tintLevels ? 1.0f : 0.0f;
  std::memcpy(views_[slot].mapped(), &view, sizeof(view));
  gpu::TimestampPool& t = *timestamps_[slot];
  t.reset();
  splatMarks_[slot] = drawMarks_[slot] = kNoMark;
  splatted_[slot] = false;
  frameNumbers_[slot] = ++framesRecorded_;
  t.write(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
  ClothAdvanceJob{&cloth_, crowd_, &buffers_}.record(cmd, programs_);
  t.write(cmd);
  gpu::computeToComputeBarrier(cmd);
  ClothMarkJob{&cloth_, crowd_, &buffers_, &views_[slot]}.record(cmd, programs_);
  t.write(cmd);
  ClothDecodeJob{&cloth_, &buffers_}.record(cmd, programs_);
  t.write(cmd);
  // The frame's statistics, after the decode's mark so they cost the timings nothing; the next
  // frame's clear of the counters waits for this copy, and the host reads it after the fence.
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
  const VkBufferCopy counters{0, 0, kCounterBytes}, draws{0, kCounterBytes, kDrawBytes};
  vkCmdCopyBuffer(cmd, buffers_.counters.get(), statsCopies_[slot].get(), 1, &counters);
  vkCmdCopyBuffer(cmd, buffers_.draws.get(), statsCopies_[slot].get(), 1, &draws);
  gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                     VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_HOST_BIT);
}

void ClothLayer::recordSplat(VkCommandBuffer cmd, const gpu::Buffer& visibility, uint32_t slot) {
  if (!clothSplattable(cloth_)) return;
  gpu::TimestampPool& t = *timestamps_[slot];
  splatMarks_[slot] = t.write(cmd);
  gpu::computeToComputeBarrier(cmd);  // after the joints' splat into the same buffer
  ClothSplatJob{&cloth_, crowd_, &buffers_, &views_[slot], &visibility}.record(cmd, programs_);
  t.write(cmd);
  splatted_[slot] = true;
}

void ClothLayer::recordDraw(VkCommandBuffer cmd, uint32_t slot) {
  gpu::TimestampPool& t = *timestamps_[slot];
  drawMarks_[slot] = t.write(cmd);
  ClothDrawJob draw{&cloth_,        crowd_, &buffers_, &views_[slot], options_.tintLevels,
                    splatted_[slot]};
  draw.record(cmd, programs_);
  t.write(cmd);
}

ClothStats ClothLayer::stats(uint32_t slot) const {
  THRONG_CHECK(slot < render::kFramesInFlight, "frame slot ", slot, " out of range");
  const auto* bytes = static_cast<const uint8_t*>(statsCopies_[slot].mapped());
  gpu_types::ClothCounters c;
  std::memcpy(&c, bytes, sizeof(c));
  uint32_t draws[kClothLevels * 5];
  std::memcpy(draws, bytes + kCounterBytes, sizeof(draws));
  ClothStats stats{std::min(c.usedStates, buffers_.maxUsedStates),
                   c.demoted,
                   std::min(c.fineCursor, buffers_.fineBudget),
                   {}};
  for (uint32_t L = 0; L < kClothLevels; ++L) stats.capes[L] = draws[5 * L + 1];
  return stats;
}

ClothTimings ClothLayer::timings(uint32_t slot) const {
  const gpu::TimestampPool& t = *timestamps_[slot];
  std::vector<uint64_t> ticks = t.fetch();
  if (ticks.size() < 4) return {};
  ClothTimings out{t.millisecondsBetween(ticks, 0, 1), t.millisecondsBetween(ticks, 1, 2),
                   t.millisecondsBetween(ticks, 2, 3), 0.0, 0.0};
  if (splatMarks_[slot] != kNoMark)
    out.splatMs = t.millisecondsBetween(ticks, splatMarks_[slot], splatMarks_[slot] + 1);
  if (drawMarks_[slot] != kNoMark)
    out.drawMs = t.millisecondsBetween(ticks, drawMarks_[slot], drawMarks_[slot] + 1);
  return out;
}

}  // namespace throng::secondary
