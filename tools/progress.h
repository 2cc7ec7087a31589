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
  // For work known only as named stages: `done` of the total units are finished and `name`
  // starts. The bar shows the stage; without a terminal every stage gets its own line.
  void stage(long long done, const std::string& name);
  void finish();  // ends the bar's line on a terminal

 private:
  std::string what_;
  long long total_;
  long long lastLine_ = 0;
  bool terminal_;
  bool drawn_ = false;
  void draw(long long done, const std::string& label);
  std::chrono::steady_clock::time_point start_;
};

}  // namespace throng::tools
