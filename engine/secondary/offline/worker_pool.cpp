#include "secondary/offline/worker_pool.h"

#include <system_error>

namespace throng::secondary {

WorkerPool::WorkerPool(unsigned threads) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  // A thread that cannot start leaves the pool with the ones that did (the caller's thread
  // works too), rather than unwinding past joinable threads.
  workers_.reserve(threads);
  for (unsigned i = 1; i < threads; ++i) {
    try {
      workers_.emplace_back([this] { loop(); });
    } catch (const std::system_error&) {
      break;
    }
  }
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

// Takes indices until none is left; the caller holds no lock.
void WorkerPool::work() {
  for (;;) {
    size_t i;
    const std::function<void(size_t)>* job;
    {
      std::lock_guard lock(mutex_);
      if (next_ >= count_) return;
      i = next_++;
      job = job_;
    }
    std::exception_ptr error;
    try {
      (*job)(i);
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard lock(mutex_);
    if (error) errors_[i] = error;
    if (++finished_ == count_) done_.notify_all();
  }
}

void WorkerPool::loop() {
  uint64_t seen = 0;
  for (;;) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
      if (stop_) return;
      seen = generation_;
    }
    work();
  }
}

void WorkerPool::run(size_t count, const std::function<void(size_t)>& job) {
  if (count == 0) return;
  {
    std::lock_guard lock(mutex_);
    job_ = &job;
    count_ = count;
    next_ = 0;
    finished_ = 0;
    errors_.assign(count, nullptr);
    ++generation_;
  }
  wake_.notify_all();
  work();
  std::unique_lock lock(mutex_);
  done_.wait(lock, [&] { return finished_ == count_; });
  job_ = nullptr;
  count_ = 0;
  for (const std::exception_ptr& e : errors_)
    if (e) std::rethrow_exception(e);
}

}  // namespace throng::secondary
