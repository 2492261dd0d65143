#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace airis::engine {

/// Runs a loop over [0, n) on a fixed number of threads: the calling thread and threads - 1
/// workers that live as long as the pool. Indices are handed out in small chunks to whichever
/// thread asks first, so a worker the OS does not schedule (a busy machine) only leaves more for
/// the others; each index is run by exactly one thread. A body whose iterations touch disjoint
/// state therefore gives the same results for any thread count and any schedule. The Simulation
/// steps its vehicles on one; the Python module's vectorized environments step their worlds on
/// another.
class WorkerPool {
 public:
  /// @param threads 1 to 64 (1: everything on the calling thread, no workers). Throws
  /// std::invalid_argument outside that range.
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  /// Calls body(i) for every i in [0, n) and returns when all have returned. An index whose body
  /// throws does not stop the others; afterwards the exception of the lowest such index is
  /// rethrown.
  void Run(std::size_t n, const std::function<void(std::size_t)>& body);

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

 private:
  void WorkerLoop();
  void RunChunks();

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable start_;
  std::condition_variable done_;
  std::size_t generation_ = 0;  // incremented by each Run
  // generation_ as workers may read it without the lock while they spin between Runs.
  std::atomic<std::size_t> published_{0};
  bool open_ = false;           // workers may still join the current Run
  std::atomic<int> active_{0};  // workers inside the current Run (changed under mutex_)
  bool stopping_ = false;
  std::size_t n_ = 0;
  std::size_t chunk_ = 1;
  std::atomic<std::size_t> next_{0};
  const std::function<void(std::size_t)>* body_ = nullptr;
  std::mutex error_mutex_;
  std::size_t error_index_ = 0;
  std::exception_ptr error_;
};

/// Calls body(i) for every i in [0, n): on `pool` when there is one with several threads, else in
/// order on the calling thread, with no pool overhead (the body is inlined). Exceptions as
/// WorkerPool::Run on a pool; in order, the first one stops the loop.
template <class Body>
void ParallelFor(WorkerPool* pool, std::size_t n, Body&& body) {
  if (pool == nullptr || pool->threads() == 1 || n < 2) {
    for (std::size_t i = 0; i < n; ++i) body(i);
    return;
  }
  pool->Run(n, std::function<void(std::size_t)>(std::ref(body)));
}

}  // namespace airis::engine
