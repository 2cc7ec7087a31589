#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/log.h"

namespace throng::tools {
namespace {

// "4.2 s" under a minute, else "3 min 05 s": an ETA needs no more digits than that.
std::string formatSeconds(double seconds) {
  char text[48];
  if (seconds < 60.0)
    std::snprintf(text, sizeof text, "%.1f s", seconds);
  else
    std::snprintf(text, sizeof text, "%d min %02d s", int(seconds / 60.0),
                  int(std::fmod(seconds, 60.0)));
  return text;
}

}  // namespace

Progress::Progress(std::string what, long long total)
    : what_(std::move(what)),
      total_(std::max(1LL, total)),
      terminal_(::isatty(2) == 1),
      start_(std::chrono::steady_clock::now()) {}

void Progress::draw(long long done, const std::string& label) {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = std::clamp(double(done) / double(total_), 0.0, 1.0);
  constexpr int kWidth = 30;
  const int filled = int(fraction * kWidth);
  std::string bar(size_t(filled), '=');
  if (filled < kWidth) bar += '>' + std::string(size_t(kWidth - filled - 1), ' ');
  // No estimate before the first unit is done: it would be a division by zero, not a guess.
  const std::string eta =
      done > 0 ? concat("ETA ", formatSeconds(seconds * (1.0 - fraction) / fraction)) : "ETA -";
  // Trailing spaces wipe what a longer earlier label left on the line.
  std::fprintf(stderr, "\r%s [%s] %lld/%lld  %s, %s%s%s   ", what_.c_str(), bar.c_str(), done,
               total_, formatSeconds(seconds).c_str(), eta.c_str(), label.empty() ? "" : "  ",
               label.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::update(long long done, const std::string& detail) {
  if (terminal_) {
    draw(done, {});
    return;
  }
  const long long step = std::max(1LL, total_ / 10);
  if (total_ >= 10 && done / step > lastLine_ / step) {
    lastLine_ = done;
    logInfo(concat(what_, " ", done, "/", total_, detail.empty() ? "" : "  ", detail));
  }
}

void Progress::stage(long long done, const std::string& name) {
  if (terminal_) {
    draw(done, name);
    return;
  }
  logInfo(concat(what_, ": ", name, " (", done, "/", total_, " done)"));
}

void Progress::finish() {
  if (terminal_ && drawn_) std::fputc('\n', stderr);
  drawn_ = false;
}

}  // namespace throng::tools
