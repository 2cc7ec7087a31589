#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include "core/error.h"
#include "core/log.h"

namespace throng::tools {

Progress::Progress(std::string what, long long total)
    : what_(std::move(what)),
      total_(std::max(1LL, total)),
      terminal_(::isatty(2) == 1),
      start_(std::chrono::steady_clock::now()) {}

void Progress::update(long long done, const std::string& detail) {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction = std::clamp(double(done) / double(total_), 0.0, 1.0);
  const double eta = done > 0 ? seconds * (1.0 - fraction) / fraction : 0.0;
  if (terminal_) {
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth);
    std::string bar(size_t(filled), '=');
    if (filled < kWidth) bar += '>' + std::string(size_t(kWidth - filled - 1), ' ');
    std::fprintf(stderr, "\r%s [%s] %lld/%lld  %.1f s, ETA %.1f s ", what_.c_str(), bar.c_str(),
                 done, total_, seconds, eta);
    std::fflush(stderr);
    drawn_ = true;
    return;
  }
  const long long step = std::max(1LL, total_ / 10);
  if (total_ >= 10 && done / step > lastLine_ / step) {
    lastLine_ = done;
    logInfo(concat(what_, " ", done, "/", total_, detail.empty() ? "" : "  ", detail));
  }
}

void Progress::finish() {
  if (terminal_ && drawn_) std::fputc('\n', stderr);
  drawn_ = false;
}

}  // namespace throng::tools
