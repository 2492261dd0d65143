#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace airis::engine {

/// Runs a loop over [0, n) on a fixed number of threads: the calling thread and threads - 1
/// workers that live as long as the pool. Thread t owns the t-th of `threads` contiguous shares of
/// the indices and takes them first, in small chunks; a thread that has run out of its own share
/// helps with what is left of the others'. So with the same n from one Run to the next, each
/// thread runs the same indices (a simulation's vehicle stays in one core's cache from tick to
/// tick), and a worker the OS does not schedule (a busy machine) only leaves more for the others.
/// Each index is run by exactly one thread: a body whose iterations touch disjoint state gives the
/// same results for any thread count and any schedule. The Simulation steps its vehicles on one;
/// the Python module's vectorized environments step their worlds on another.
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
  /// rethrown. Not reentrant: one Run at a time, from one thread.
  void Run(std::size_t n, const std::function<void(std::size_t)>& body);

  int threads() const { return threads_; }

 private:
  // One thread's share of a Run: the indices [next, end) not taken yet. A cache line each, so a
  // thread taking its own indices does not touch the line of another's.
  struct alignas(64) Share {
    std::atomic<std::size_t> next{0};
    std::size_t end = 0;
  };

  void WorkerLoop(int self);
  // Runs chunks of share `self`, then of the others in turn, until none is left.
  void RunShares(int self);
  void RunIndex(std::size_t i);

  int threads_;
  std::unique_ptr<Share[]> shares_;  // one per thread; 0 is the caller's
  std::vector<std::thread> workers_;
  // The hand-over, without locks (a Run of a swarm's tick lasts tens of microseconds, and each
  // lock taken on both sides moved a cache line between the cores: 2 us a Run with a mutex and
  // condition variables, against about 0.3 us so). A Run publishes an odd ticket 2g + 1 ("Run g
  // open") and, once the caller has run out of indices, the even 2g + 2 ("closed"). A worker
  // that sees an open ticket counts itself in `active_`, then looks at the ticket again: still
  // open, it takes part; closed, it counts itself out (both sides use sequentially consistent
  // order, so a worker either is seen by the caller's wait or sees the Run closed). The caller
  // returns when `active_` is 0. Both sides spin first, then sleep in futex waits on the same
  // atomics. The ticket wraps around (parity and equality are what count).
  alignas(64) std::atomic<std::uint32_t> ticket_{0};
  std::atomic<bool> stopping_{false};  // set by the destructor, with a new ticket
  alignas(64) std::atomic<int> active_{0};
  alignas(64) std::size_t chunk_ = 1;
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
