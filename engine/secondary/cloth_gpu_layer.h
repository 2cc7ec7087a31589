#pragma once
// Capes on a rendered crowd: owns the uploaded database, the crowd's cloth buffers, the programs
// and per-frame-slot view uniforms and timestamps, and records the cloth passes where the frame
// (scene/frame.h) puts them: advance, mark, decode after the synthesis (the secondary-motion
// stage); the splat of far capes into the joint renderer's visibility buffer when it splats; the
// draw inside the render pass.
#include <memory>
#include <vector>

#include "gpu/timestamps.h"
#include "render/camera.h"
#include "render/crowd_renderer.h"
#include "secondary/cloth_gpu_jobs.h"
#include "secondary/cloth_view.h"

namespace throng::secondary {

struct ClothLayerOptions {
  ClothLodSettings lod;
  bool tintLevels = false;                 // colour capes by garment level
  uint64_t fineBudgetBytes = 48ull << 20;  // decoded vertices above the coarsest level
};

// GPU time of the cloth passes in one frame (timestamps), milliseconds.
struct ClothTimings {
  double advanceMs = 0.0, markMs = 0.0, decodeMs = 0.0, splatMs = 0.0, drawMs = 0.0;
  double totalMs() const { return advanceMs + markMs + decodeMs + splatMs + drawMs; }
};

class ClothLayer {
 public:
  ClothLayer(const gpu::Context& context, const ClothDatabase& db, const crowd::CrowdBuffers& crowd,
             VkFormat colorFormat, VkFormat depthFormat, const ClothLayerOptions& options = {});

  // The passes of a frame recorded into `frameSlot` (< render::kFramesInFlight), in this order.
  // Record a slot again only after its previous frame completed (its uniforms and timestamps
  // are reused). The compute passes, after the synthesis (their own barriers):
  void recordCompute(VkCommandBuffer cmd, const render::Camera& camera, uint32_t width,
                     uint32_t height, uint32_t frameSlot);
  // Far capes into the joint renderer's visibility buffer (when the renderer splats):
  void recordSplat(VkCommandBuffer cmd, const gpu::Buffer& visibility, uint32_t frameSlot);
  // The capes' draw inside the render pass, after the joints (depth-tested with them):
  void recordDraw(VkCommandBuffer cmd, uint32_t frameSlot);
  // After the frame recorded into `frameSlot` completed.
  ClothTimings timings(uint32_t frameSlot) const;
  // What that frame's mark pass counted (states decoded, capes per level), from a copy the frame
  // made of its counters: with frames in flight the live counters may already belong to the next
  // frame.
  ClothStats stats(uint32_t frameSlot) const;
  // Frames recorded so far, and which of them `frameSlot` holds (1-based; 0: none yet).
  uint64_t framesRecorded() const { return framesRecorded_; }
  uint64_t frameNumber(uint32_t frameSlot) const { return frameNumbers_.at(frameSlot); }
  // The live counters (right after a frame completed with no other in flight).
  ClothStats stats() const { return readClothStats(buffers_); }

  ClothLayerOptions& options() { return options_; }
  const ClothGpuData& gpuData() const { return cloth_; }
  const ClothCrowdBuffers& buffers() const { return buffers_; }

 private:
  const crowd::CrowdBuffers* crowd_ = nullptr;
  ClothLayerOptions options_;
  ClothPrograms programs_;
  ClothGpuData cloth_;
  ClothCrowdBuffers buffers_;
  std::vector<gpu::Buffer> views_;
  std::vector<std::unique_ptr<gpu::TimestampPool>> timestamps_;
  std::vector<gpu::Buffer> statsCopies_;          // per slot: ClothCounters, then the draws
  std::vector<uint32_t> splatMarks_, drawMarks_;  // per slot: first of the two marks, or none
  std::vector<bool> splatted_;                    // per slot: far capes went to the splat
  std::vector<uint64_t> frameNumbers_;            // per slot: the frame recorded into it
  uint64_t framesRecorded_ = 0;
};

}  // namespace throng::secondary
