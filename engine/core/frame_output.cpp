#include "core/frame_output.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>

#include <sys/resource.h>
#include <unistd.h>

#include "core/clock.h"
#include "core/error.h"
#include "core/file_io.h"

namespace throng {
namespace {
// At the lowest priority, one worker per hardware thread (1 to 8): they take only the idle time
// the frame loop leaves, and on a CPU device it leaves that on every core in short pieces (one
// device thread waiting for another, the readback) that one worker cannot fill while it also
// waits for the disk. At the caller's priority, half the hardware threads: the other half renders.
int workerCount(const FrameOutputOptions& options) {
  if (options.video) return 1;
  if (options.workers > 0) return std::min(options.workers, 8);
  const int threads = int(std::thread::hardware_concurrency());
  return std::clamp(options.lowPriority ? threads : threads / 2, 1, 8);
}

// The calling thread's nice value, raised to the lowest priority first when `lower` (Linux
// schedules threads one by one, so this leaves the frame loop's threads as they are). A refusal
// leaves the priority as it was: encoding then competes, as it would anywhere else.
int workerPriority(bool lower) {
  const auto thread = id_t(gettid());
  if (lower) setpriority(PRIO_PROCESS, thread, 19);
  errno = 0;
  const int nice = getpriority(PRIO_PROCESS, thread);
  return errno == 0 ? nice : 0;
}
}  // namespace

FrameOutput::FrameOutput(const FrameOutputOptions& options) : options_(options) {
  if (options_.queueDepth < 1 || options_.queueDepth > 64)
    fail("frame output: queue depth ", options_.queueDepth, " is outside 1..64");
  if (options_.video)
    video_.emplace(*options_.video, VideoOptions{options_.width, options_.height, options_.fps});
  stats_.workers = workerCount(options_);
  options_.queueDepth = std::max(options_.queueDepth, stats_.workers + 1);  // every worker busy
  spares_.reserve(size_t(options_.queueDepth));  // so a worker's push_back never allocates
  try {
    for (int k = 0; k < stats_.workers; ++k) workers_.emplace_back([this] { run(); });
  } catch (...) {  // a thread that cannot start: the started ones are stopped before unwinding
    {
      std::lock_guard lock(mutex_);
      closing_ = true;
    }
    changed_.notify_all();
    joinWorkers();
    throw;
  }
}

FrameOutput::~FrameOutput() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
    queue_.clear();
  }
  changed_.notify_all();
  joinWorkers();
  video_.reset();  // an unfinished video's temporary file is removed
}

void FrameOutput::joinWorkers() {
  for (std::thread& worker : workers_)
    if (worker.joinable()) worker.join();
}

void FrameOutput::rethrow() {
  if (error_) {
    std::exception_ptr e = error_;
    error_ = nullptr;
    std::rethrow_exception(e);
  }
}

ImageRgba8 FrameOutput::spareImage() {
  std::lock_guard lock(mutex_);
  if (spares_.empty()) return {};
  ImageRgba8 image = std::move(spares_.back());
  spares_.pop_back();
  return image;
}

void FrameOutput::push(ImageRgba8 frame, int index) {
  auto start = std::chrono::steady_clock::now();
  std::unique_lock lock(mutex_);
  changed_.wait(lock,
                [&] { return error_ || int(queue_.size()) + inFlight_ < options_.queueDepth; });
  stats_.waitedMs += millisecondsSince(start);
  rethrow();
  queue_.push_back({std::move(frame), index});
  lock.unlock();
  changed_.notify_all();
}

void FrameOutput::finish() {
  {
    std::unique_lock lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  joinWorkers();
  std::lock_guard lock(mutex_);
  rethrow();
  if (video_) {
    video_->finish();
    video_.reset();
  }
}

FrameOutputStats FrameOutput::stats() const {
  std::lock_guard lock(mutex_);
  return stats_;
}

void FrameOutput::run() {
  const int nice = workerPriority(options_.lowPriority);
  {
    std::lock_guard lock(mutex_);
    stats_.workerNice = nice;
  }
  PngEncoder png;  // this worker's: its buffers serve every frame it encodes
  for (;;) {
    Job job;
    {
      std::unique_lock lock(mutex_);
      changed_.wait(lock, [&] { return closing_ || !queue_.empty(); });
      if (queue_.empty() || error_) return;
      job = std::move(queue_.front());
      queue_.pop_front();
      ++inFlight_;  // the slot frees only once the frame is encoded: depth bounds memory
    }
    auto start = std::chrono::steady_clock::now();
    try {
      encode(job, png);
    } catch (...) {
      std::lock_guard lock(mutex_);
      if (!error_) error_ = std::current_exception();
      --inFlight_;
      queue_.clear();
      changed_.notify_all();
      return;
    }
    {
      std::lock_guard lock(mutex_);
      --inFlight_;
      stats_.encodeMs += millisecondsSince(start);
      ++stats_.frames;
      // At most a queue's worth of buffers kept: as many as can be out at once.
      if (int(spares_.size()) < options_.queueDepth) spares_.push_back(std::move(job.image));
    }
    changed_.notify_all();
  }
}

void FrameOutput::encode(const Job& job, PngEncoder& png) {
  if (options_.pngFolder) {
    char name[32];
    std::snprintf(name, sizeof(name), "frame_%04d.png", job.index);
    writeFileAtomic(*options_.pngFolder / name, png.encode(job.image));
  }
  if (video_) video_->write(job.image);
}

}  // namespace throng
