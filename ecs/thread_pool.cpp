#include "ecs/thread_pool.h"

namespace sg::ecs {

ThreadPool::ThreadPool(unsigned workers) {
  threads_.reserve(workers);
  for (unsigned i = 0; i < workers; ++i) threads_.emplace_back([this] { work(); });
}

ThreadPool::~ThreadPool() {
  {
    const std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  batch_started_.notify_all();
  for (std::thread& thread : threads_) thread.join();
}

unsigned ThreadPool::default_workers() {
  const unsigned hardware = std::thread::hardware_concurrency();
  return hardware > 1 ? hardware - 1 : 0;
}

void ThreadPool::wake() {
  if (threads_.empty()) return;
  {
    const std::lock_guard lock(mutex_);
    ++wakes_;
  }
  batch_started_.notify_all();
}

void ThreadPool::run(std::size_t count, const std::function<void(std::size_t)>& task) {
  if (count == 0) return;
  std::size_t batch = 0;
  {
    const std::lock_guard lock(mutex_);
    task_ = &task;
    count_ = count;
    next_ = 0;
    unfinished_ = count;
    error_ = nullptr;
    batch = ++batch_;
  }
  batch_started_.notify_all();
  drain(batch);
  std::unique_lock lock(mutex_);
  batch_finished_.wait(lock, [this] { return unfinished_ == 0; });
  if (error_ != nullptr) std::rethrow_exception(error_);
}

void ThreadPool::drain(std::size_t batch) {
  std::unique_lock lock(mutex_);
  // A worker that wakes late may find the next batch already running: it joins that one only
  // through its own wake-up, never with this batch's number.
  while (batch_ == batch && next_ < count_) {
    const std::size_t index = next_++;
    const std::function<void(std::size_t)>& task = *task_;  // alive until this index finishes
    lock.unlock();
    std::exception_ptr error;
    try {
      task(index);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error != nullptr && error_ == nullptr) error_ = error;
    if (--unfinished_ == 0) batch_finished_.notify_all();
  }
}

void ThreadPool::spin_for_batch(std::size_t seen) const {
  const auto until = std::chrono::steady_clock::now() + spin_time;
  while (batch_.load() == seen && !stopping_.load() && std::chrono::steady_clock::now() < until) {
    std::this_thread::yield();
  }
}

void ThreadPool::work() {
  std::size_t seen = 0;
  std::size_t seen_wakes = 0;
  for (;;) {
    spin_for_batch(seen);
    std::unique_lock lock(mutex_);
    batch_started_.wait(lock, [&] { return stopping_ || batch_ != seen || wakes_ != seen_wakes; });
    if (stopping_) return;
    seen_wakes = wakes_;
    if (batch_ == seen) continue;  // woken ahead of a batch: spin for it
    seen = batch_;
    lock.unlock();
    drain(seen);
  }
}

}  // namespace sg::ecs
