#include "tools/python/worker_pool.h"

#include <stdexcept>
#include <string>

namespace airis::python {

WorkerPool::WorkerPool(int threads) {
  if (threads < 1 || threads > 64) {
    throw std::invalid_argument("threads must be between 1 and 64 (got " + std::to_string(threads) +
                                ")");
  }
  errors_.resize(static_cast<std::size_t>(threads));
  for (int w = 1; w < threads; ++w) workers_.emplace_back([this, w] { WorkerLoop(w); });
}

WorkerPool::~WorkerPool() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  start_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void WorkerPool::RunBlock(int block) {
  const auto blocks = static_cast<std::size_t>(threads());
  const std::size_t b = static_cast<std::size_t>(block);
  const std::size_t begin = n_ * b / blocks;
  const std::size_t end = n_ * (b + 1) / blocks;
  try {
    for (std::size_t i = begin; i < end; ++i) (*body_)(i);
  } catch (...) {
    errors_[b] = std::current_exception();
  }
}

void WorkerPool::WorkerLoop(int worker) {
  std::size_t seen = 0;
  for (;;) {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
    }
    RunBlock(worker);
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      --pending_;
    }
    done_.notify_one();
  }
}

void WorkerPool::Run(std::size_t n, const std::function<void(std::size_t)>& body) {
  for (auto& e : errors_) e = nullptr;
  n_ = n;
  body_ = &body;
  if (!workers_.empty()) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      pending_ = static_cast<int>(workers_.size());
      ++generation_;
    }
    start_.notify_all();
  }
  RunBlock(0);
  if (!workers_.empty()) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return pending_ == 0; });
  }
  body_ = nullptr;
  for (const auto& e : errors_) {
    if (e) std::rethrow_exception(e);
  }
}

}  // namespace airis::python
