#include "view_lod.h"

#include <bit>

#include "core/error.h"

namespace throng::tools {

LodStats summarizeMasks(std::span<const synth::CoverageMask> masks) {
  LodStats stats;
  stats.enabled = true;
  for (const synth::CoverageMask& m : masks) {
    stats.activeJoints += std::popcount(synth::maskBits(m));
    ++stats.levels[std::min<uint32_t>(m.level, 2)];
  }
  return stats;
}

LodStats fullDetailStats(uint32_t characters, uint32_t jointsPerCharacter) {
  LodStats stats;
  stats.activeJoints = uint64_t(characters) * jointsPerCharacter;
  stats.levels = {0, 0, characters};
  return stats;
}

void LodReadback::record(VkCommandBuffer cmd, const synth::CrowdSynth& synth, uint32_t slot,
                         uint64_t frame) {
  if (synth.lod) record(cmd, synth.masks, synth.crowd.count, slot, frame);
}

void LodReadback::record(VkCommandBuffer cmd, const gpu::Buffer& masks, uint32_t count, uint32_t slot,
                         uint64_t frame) {
  THRONG_CHECK(slot < render::kPresenterFrames, "frame slot ", slot, " out of range");
  Slot& s = slots_[slot];
  const VkDeviceSize bytes = VkDeviceSize(count) * sizeof(synth::CoverageMask);
  // The slot's fence was waited and its copy collected: its old buffer is free to replace.
  if (!s.buffer || s.buffer.size() < bytes)
    s.buffer = gpu::Buffer(context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           gpu::MemoryUse::HostVisible);
  VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  before.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  before.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       0, 1, &before, 0, nullptr, 0, nullptr);
  VkBufferCopy region{0, 0, bytes};
  vkCmdCopyBuffer(cmd, masks.get(), s.buffer.get(), 1, &region);
  VkMemoryBarrier after{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  after.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  after.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &after, 0, nullptr, 0, nullptr);
  s.count = count;
  s.frame = frame;
  s.pending = true;
}

void LodReadback::collect(uint32_t slot) {
  Slot& s = slots_[slot];
  if (!s.pending) return;
  s.pending = false;
  if (s.frame < latest_.frame) return;
  LodStats stats = summarizeMasks(s.buffer.hostSpan<const synth::CoverageMask>().first(s.count));
  stats.frame = s.frame;
  latest_ = stats;
}

void LodReadback::reset() {
  for (Slot& s : slots_) s.pending = false;
  latest_ = {};
}

}  // namespace throng::tools
