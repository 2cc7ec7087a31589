#pragma once
// Live statistics of `throng view`: frames per second over half-second windows, the GPU
// time of each pass (timestamps of the frame that last completed) and, with --cloth, what the
// cloth layer did in the newest completed frame.
#include <cstdint>
#include <vector>

#include "secondary/cloth_gpu_layer.h"
#include "stats.h"

namespace throng::tools {

// One completed frame of the cloth layer: its counters (copied by that frame) and GPU times.
struct ClothFrameStats {
  uint64_t frame = 0;  // the layer's frame number (0: none yet)
  secondary::ClothStats capes;
  secondary::ClothTimings gpu;
};

// How the visible capes were drawn: levels 0-1 as full and mid triangle meshes, level 2 (and
// level 3 when the device cannot splat) as the coarse mesh, level 3 splatted by a compute pass.
struct CapeCounts {
  uint32_t triangles = 0, coarse = 0, splatted = 0;
};
inline CapeCounts capeCounts(const secondary::ClothStats& s, bool splat) {
  return {s.capes[0] + s.capes[1], s.capes[2] + (splat ? 0u : s.capes[3]), splat ? s.capes[3] : 0u};
}

struct PassTimes {
  double synthesisMs = 0.0;
  double renderMs = 0.0;
  double panelMs = 0.0;
};

class ViewStats {
 public:
  void frameDone(double wallSeconds) {
    ++frames_;
    windowSeconds_ += wallSeconds;
    ++windowFrames_;
    if (windowSeconds_ >= 0.5) {
      fps_ = windowFrames_ / windowSeconds_;
      frameMs_ = 1000.0 * windowSeconds_ / windowFrames_;
      windowSeconds_ = 0.0;
      windowFrames_ = 0;
    }
    totalSeconds_ += wallSeconds;
  }
  void passTimes(const PassTimes& t) {
    last_ = t;
    synthesis_.push_back(t.synthesisMs);
    render_.push_back(t.renderMs);
    panel_.push_back(t.panelMs);
  }

  // Frames may complete out of slot order: the newest frame's counters are kept.
  void clothFrame(const ClothFrameStats& c) {
    if (c.frame == 0) return;
    if (c.frame > cloth_.frame) cloth_ = c;
    clothMs_.push_back(c.gpu.totalMs());
  }
  // After a respawn the layer counts frames from 1 again.
  void resetCloth() { cloth_ = {}; }
  const ClothFrameStats& cloth() const { return cloth_; }
  double clothMedianMs() const { return median(clothMs_); }

  uint64_t frames() const { return frames_; }
  // Before the first half-second has passed: the average so far.
  double fps() const {
    return fps_ > 0.0 ? fps_ : (totalSeconds_ > 0.0 ? frames_ / totalSeconds_ : 0.0);
  }
  double frameMs() const {
    return fps_ > 0.0 ? frameMs_ : (frames_ ? 1000.0 * totalSeconds_ / frames_ : 0.0);
  }
  double averageFps() const { return totalSeconds_ > 0.0 ? frames_ / totalSeconds_ : 0.0; }
  const PassTimes& last() const { return last_; }
  PassTimes medians() const { return {median(synthesis_), median(render_), median(panel_)}; }

 private:
  uint64_t frames_ = 0;
  double windowSeconds_ = 0.0, totalSeconds_ = 0.0;
  int windowFrames_ = 0;
  double fps_ = 0.0, frameMs_ = 0.0;
  PassTimes last_;
  std::vector<double> synthesis_, render_, panel_;
  ClothFrameStats cloth_;
  std::vector<double> clothMs_;
};

}  // namespace throng::tools
