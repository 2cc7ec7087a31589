#pragma once
// One frame of the crowd: synthesis passes, then the draw, with GPU timestamps around each.
// Shared by the headless frame dumper and the viewer (they differ only in the target image).
#include "gpu/timestamps.h"
#include "render/crowd_renderer.h"
#include "synth/crowd_synth.h"

namespace throng::render {

struct FrameTargets {
  VkImage color = VK_NULL_HANDLE;
  VkImageView colorView = VK_NULL_HANDLE;
  VkImage depth = VK_NULL_HANDLE;
  VkImageView depthView = VK_NULL_HANDLE;
  uint32_t width = 0, height = 0;
  VkImageLayout finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
};

struct FrameTimestamps {
  uint32_t start = 0, synthesized = 0, rendered = 0;
};

struct FrameTimings {
  double synthesisMs = 0.0;
  double renderMs = 0.0;
};

FrameTimestamps recordCrowdFrame(VkCommandBuffer cmd, const gpu::Context& context, const synth::SynthPrograms& programs,
                                 const synth::CrowdSynth& synth, CrowdRenderer& renderer, const Camera& camera,
                                 float groundExtent, const FrameTargets& targets, float dt, gpu::TimestampPool& timestamps,
                                 uint32_t frameSlot = 0, const anim::SpeedRetarget& retarget = {},
                                 bool tintLevels = false);

FrameTimings readFrameTimings(const gpu::TimestampPool& timestamps, const FrameTimestamps& marks);

}  // namespace throng::render
