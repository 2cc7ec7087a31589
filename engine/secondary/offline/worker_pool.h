#pragma once
// A fixed set of threads that run index ranges of independent jobs (expansions), so the
// exploration does not start threads for every batch.
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace throng::secondary {

class WorkerPool {
 public:
  explicit WorkerPool(unsigned threads);  // 0: hardware concurrency
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  unsigned threads() const { return unsigned(workers_.size()) + 1; }
  // Calls job(i) for every i < count on the pool and the calling thread; rethrows the first
  // exception a job threw (by lowest index, so the error does not depend on timing).
  void run(size_t count, const std::function<void(size_t)>& job);

 private:
  void loop();
  void work();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(size_t)>* job_ = nullptr;
  size_t count_ = 0, next_ = 0, finished_ = 0;
  uint64_t generation_ = 0;
  bool stop_ = false;
  std::vector<std::exception_ptr> errors_;
};

}  // namespace throng::secondary
