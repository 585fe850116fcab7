#pragma once

#include <condition_variable>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sg::ecs {

// A fixed set of worker threads that run the tasks of one batch at a time, for splitting a
// query into chunks (Query::for_each_parallel).
//
// Contract:
// - run(count, task) calls task(i) exactly once for every i in [0, count), on the workers and
//   on the calling thread, and returns when every call has returned. Tasks of one batch run
//   concurrently, so they must not write the same data.
// - One batch at a time: run is not reentrant and must not be called from a task, nor from two
//   threads at once.
// - If tasks throw, the remaining tasks still run and run rethrows the first exception.
class ThreadPool {
 public:
  // `workers` threads besides the caller; 0 runs everything on the calling thread.
  explicit ThreadPool(unsigned workers = default_workers());
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;
  ~ThreadPool();

  // Threads that run a batch's tasks, the caller included.
  unsigned thread_count() const { return static_cast<unsigned>(threads_.size()) + 1; }

  void run(std::size_t count, const std::function<void(std::size_t)>& task);

  // One worker per hardware thread besides the caller.
  static unsigned default_workers();

 private:
  void work();
  // Claims and runs tasks of batch number `batch` until none are left or another batch began.
  void drain(std::size_t batch);

  std::mutex mutex_;
  std::condition_variable batch_started_;
  std::condition_variable batch_finished_;
  const std::function<void(std::size_t)>* task_ = nullptr;
  std::size_t count_ = 0;
  std::size_t next_ = 0;        // first unclaimed task of the batch
  std::size_t unfinished_ = 0;  // claimed or unclaimed tasks not returned yet
  std::size_t batch_ = 0;       // number of the current batch; workers join each once
  std::exception_ptr error_;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

}  // namespace sg::ecs
