#pragma once
// GPU time per pass of the joint renderer (the visibility clear, the splat, the ground, the near
// joints, the resolve, ...), for finding where a frame's time goes. Off unless the environment
// sets THRONG_RENDER_PASS_TIMES=1: each mark is a timestamp, and on lavapipe a timestamp inside
// a render pass makes the rasterizer flush, so marks cost a little themselves; lavapipe also takes
// a timestamp at its next flush (a barrier, a render pass's end), so a mark followed by a copy
// books the copy to the pass before it. Prints the median of every pass to stderr when destroyed.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gpu/timestamps.h"

namespace throng::render {

class PassTimer {
 public:
  explicit PassTimer(const gpu::Context& context);
  ~PassTimer();
  PassTimer(const PassTimer&) = delete;
  PassTimer& operator=(const PassTimer&) = delete;

  bool enabled() const { return pool_ != nullptr; }
  // Starts a frame: the previous frame's marks are read (its work has completed by then).
  void beginFrame(VkCommandBuffer cmd);
  // The time since the previous mark is booked to `pass`.
  void mark(VkCommandBuffer cmd, const char* pass);
  // The marks since beginFrame are not booked: their work was no frame (scene::FramePreparation).
  void discardPending() { pending_.clear(); }

 private:
  void collect();  // the pending marks' times, when their frame completed
  std::unique_ptr<gpu::TimestampPool> pool_;
  std::vector<std::string> pending_;  // pass of each mark after the first
  std::map<std::string, std::vector<double>> times_;
  std::vector<std::string> order_;
};

}  // namespace throng::render
