#pragma once
// The bench's warm-up before a row is measured: at least `frames` frames, and frames for at least
// `seconds` in all. A GPU lowers its clocks while the CPU rows run; after them, an NVIDIA H100 ran
// the bench's whole-frame rows 2.5–4× slower than in a sustained frame loop (docs/performance.md).
#include <chrono>

namespace throng::tools {

class WarmUp {
 public:
  WarmUp(int frames, double seconds)
      : frames_(frames), seconds_(seconds), start_(std::chrono::steady_clock::now()) {}

  // Called after each frame: whether that frame is measured (false while warming up).
  bool measured() {
    if (!done_ && warmed_ >= frames_ &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count() >=
            seconds_)
      done_ = true;
    if (done_) return true;
    ++warmed_;
    return false;
  }

 private:
  int frames_;
  double seconds_;
  std::chrono::steady_clock::time_point start_;
  int warmed_ = 0;
  bool done_ = false;
};

}  // namespace throng::tools
