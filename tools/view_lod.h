#pragma once
// The coverage LOD's live statistics in `throng view`: each frame copies the per-character masks
// into a host-visible buffer of its own frame slot at its end; the masks are summed when that
// slot's fence has been waited (never a blocking readback in the middle of a frame).
#include <array>
#include <cstdint>
#include <span>

#include "gpu/buffer.h"
#include "viewer/window_presenter.h"
#include "synth/crowd_synth.h"

namespace throng::tools {

struct LodStats {
  bool enabled = false;
  uint64_t activeJoints = 0;          // sum over characters of the active joints
  std::array<uint64_t, 3> levels{};   // characters per level: far, mid, near
  uint64_t frame = 0;                 // the frame they describe (1-based; 0: none yet)
};

// The masks' sums (enabled = true).
LodStats summarizeMasks(std::span<const synth::CoverageMask> masks);
// Without the LOD every character is posed and drawn with every joint: all "near".
LodStats fullDetailStats(uint32_t characters, uint32_t jointsPerCharacter);

class LodReadback {
 public:
  explicit LodReadback(const gpu::Context& context) : context_(context) {}

  // At the end of frame `frame` in `slot` (whose fence has been waited): copies synth.masks
  // into the slot's buffer. Nothing when the crowd has no LOD.
  void record(VkCommandBuffer cmd, const synth::CrowdSynth& synth, uint32_t slot, uint64_t frame);
  // The same for any per-character masks buffer (several motion pairs draw from one).
  void record(VkCommandBuffer cmd, const gpu::Buffer& masks, uint32_t count, uint32_t slot, uint64_t frame);
  // After the slot's fence: sums what it copied; the newest frame collected wins.
  void collect(uint32_t slot);
  // Forget pending copies and the last statistics (a new crowd; the GPU is idle).
  void reset();
  // The newest collected frame's statistics (frame 0 before any).
  const LodStats& latest() const { return latest_; }

 private:
  struct Slot {
    gpu::Buffer buffer;
    uint32_t count = 0;
    uint64_t frame = 0;
    bool pending = false;
  };
  const gpu::Context& context_;
  Slot slots_[render::kPresenterFrames];
  LodStats latest_;
};

}  // namespace throng::tools
