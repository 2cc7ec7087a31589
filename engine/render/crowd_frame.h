#pragma once
// One frame of the crowd: synthesis passes, then the draw, with GPU timestamps around each.
// Shared by the headless frame dumper and the viewer (they differ only in the target image).
#include <functional>

#include "gpu/timestamps.h"
#include "render/crowd_renderer.h"
#include "render/offscreen_target.h"
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

// The offscreen target's images as the frame's targets, left ready for recordReadback.
FrameTargets offscreenFrameTargets(const OffscreenTarget& target);

struct FrameTimestamps {
  uint32_t start = 0, synthesized = 0, rendered = 0;
};

struct FrameTimings {
  double synthesisMs = 0.0;
  double renderMs = 0.0;
};

// Extra work a higher module adds to the frame (secondary motion): compute after the synthesis
// (before the render pass; its own barriers), splats into the joint renderer's visibility buffer
// (DrawParams::intoSplat), and draws inside the render pass after the crowd's.
struct FrameHooks {
  std::function<void(VkCommandBuffer, const DrawParams&)> afterSynthesis;
  std::function<void(VkCommandBuffer, const gpu::Buffer& visibility, const DrawParams&)> intoSplat;
  std::function<void(VkCommandBuffer, const DrawParams&)> insideRenderPass;
  // Crowd steering (storyboards): compute before the synthesis passes, which take up the
  // headings and speed weights it writes; then, inside the synthesis timing, more synthesis
  // (other motion pairs) that may change what the draw reads (joints, masks, tints).
  std::function<void(VkCommandBuffer)> beforeSynthesis;
  std::function<void(VkCommandBuffer, const synth::CoverageCamera&, DrawParams&)> moreSynthesis;
};

FrameTimestamps recordCrowdFrame(VkCommandBuffer cmd, const gpu::Context& context,
                                 const synth::SynthPrograms& programs,
                                 const synth::CrowdSynth& synth, CrowdRenderer& renderer,
                                 const Camera& camera, float groundExtent,
                                 const FrameTargets& targets, float dt,
                                 gpu::TimestampPool& timestamps, uint32_t frameSlot = 0,
                                 const anim::SpeedRetarget& retarget = {}, bool tintLevels = false,
                                 const FrameHooks* hooks = nullptr);

FrameTimings readFrameTimings(const gpu::TimestampPool& timestamps, const FrameTimestamps& marks);

}  // namespace throng::render
