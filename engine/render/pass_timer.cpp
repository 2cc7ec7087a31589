#include "render/pass_timer.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace throng::render {

namespace {
constexpr uint32_t kMarksPerFrame = 32;
}

PassTimer::PassTimer(const gpu::Context& context) {
  const char* env = std::getenv("THRONG_RENDER_PASS_TIMES");
  if (env && std::strcmp(env, "1") == 0)
    pool_ = std::make_unique<gpu::TimestampPool>(context, kMarksPerFrame);
}

PassTimer::~PassTimer() {
  if (!pool_) return;
  // The last frame's marks: the owner has waited for its frames before destroying the renderer,
  // unless recording failed (the marks were never submitted: they are dropped, and a destructor
  // neither waits for them nor throws).
  try {
    collect();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pass times: %s\n", e.what());
  }
  for (const std::string& pass : order_) {
    std::vector<double>& t = times_[pass];
    std::sort(t.begin(), t.end());
    std::fprintf(stderr, "pass %-14s median %7.3f ms  (min %.3f, max %.3f, %zu frames)\n",
                 pass.c_str(), t[t.size() / 2], t.front(), t.back(), t.size());
  }
}

void PassTimer::collect() {
  if (pending_.empty()) return;
  // Without waiting: a frame that failed while recording was never submitted, and its marks
  // are dropped (the timer expects one frame in flight at a time).
  const std::vector<uint64_t> ticks = pool_->fetchIfAvailable();
  for (size_t i = 0; i < pending_.size() && i + 1 < ticks.size(); ++i) {
    if (!times_.count(pending_[i])) order_.push_back(pending_[i]);
    times_[pending_[i]].push_back(pool_->millisecondsBetween(ticks, uint32_t(i), uint32_t(i + 1)));
  }
  pending_.clear();
}

void PassTimer::beginFrame(VkCommandBuffer cmd) {
  if (!pool_) return;
  collect();
  pool_->reset();
  pool_->write(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
}

void PassTimer::mark(VkCommandBuffer cmd, const char* pass) {
  if (!pool_ || pending_.size() + 1 >= kMarksPerFrame) return;
  pool_->write(cmd);
  pending_.emplace_back(pass);
}

}  // namespace throng::render
