#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace airis::python {

/// Runs a loop over [0, n) on a fixed number of threads: the calling thread and threads - 1
/// workers that live as long as the pool. Each thread takes one contiguous block of indices, so
/// which thread runs an index depends only on n and the thread count, and each index is run by
/// exactly one thread: a body whose iterations touch disjoint state gives the same results for any
/// thread count.
class WorkerPool {
 public:
  /// @param threads 1 to 64 (1: everything on the calling thread, no workers).
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Calls body(i) for every i in [0, n) and returns when all have returned. The first exception
  /// (of the lowest block) is rethrown after every block has finished.
  void Run(std::size_t n, const std::function<void(std::size_t)>& body);

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

 private:
  void WorkerLoop(int worker);
  void RunBlock(int block);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  std::size_t generation_ = 0;  // incremented by each Run
  int pending_ = 0;             // workers still running the current generation
  bool stopping_ = false;
  std::size_t n_ = 0;
  const std::function<void(std::size_t)>* body_ = nullptr;
  std::vector<std::exception_ptr> errors_;  // per block
};

}  // namespace airis::python
