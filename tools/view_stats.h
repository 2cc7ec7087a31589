#pragma once
// Live statistics of `throng view`: frames per second over half-second windows and the GPU
// time of each pass (timestamps of the frame that last completed).
#include <cstdint>
#include <vector>

#include "stats.h"

namespace throng::tools {

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
};

}  // namespace throng::tools
