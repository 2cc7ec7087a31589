#pragma once
// Progress of a long command: on a terminal a bar with the ETA redrawn in place on stderr,
// otherwise a plain line every tenth of the work (logs and CI stay readable).
#include <chrono>
#include <string>

namespace throng::tools {

class Progress {
 public:
  Progress(std::string what, long long total);
  // `done` units finished; `detail` is appended to plain lines (e.g. the frame's GPU times).
  void update(long long done, const std::string& detail = {});
  void finish();  // ends the bar's line on a terminal

 private:
  std::string what_;
  long long total_;
  long long lastLine_ = 0;
  bool terminal_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace throng::tools
