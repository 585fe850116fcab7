#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
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
// - After a batch, and after wake(), workers wait for the next batch spinning (yielding) for
//   spin_time before they sleep: a frame runs its batches back to back, and waking a sleeping
//   thread can take longer than its share of a batch.
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

  // A hint that a batch is coming soon: sleeping workers wake now and wait for it briefly, so a
  // caller with serial work to do first hides the threads' wake-up behind it. Optional.
  void wake();

  // One worker per hardware thread besides the caller.
  static unsigned default_workers();

  static constexpr std::chrono::microseconds spin_time{200};

 private:
  void work();
  // Returns once batch_ differs from `seen`, the pool is stopping, or spin_time has passed.
  void spin_for_batch(std::size_t seen) const;
  // Claims and runs tasks of batch number `batch` until none are left or another batch began.
  void drain(std::size_t batch);

  std::mutex mutex_;
  std::condition_variable batch_started_;
  std::condition_variable batch_finished_;
  const std::function<void(std::size_t)>* task_ = nullptr;
  std::size_t count_ = 0;
  std::size_t next_ = 0;        // first unclaimed task of the batch
  std::size_t unfinished_ = 0;  // claimed or unclaimed tasks not returned yet
  // Number of the current batch; workers join each once. Written under mutex_, read by spinning
  // workers without it.
  std::atomic<std::size_t> batch_{0};
  std::size_t wakes_ = 0;  // wake() calls
  std::exception_ptr error_;
  std::atomic<bool> stopping_{false};
  std::vector<std::thread> threads_;
};

// Runs chunk(begin, end) over [0, count) cut into pieces of `piece_size` entries (the last may
// be shorter) on `pool`, when there is one with workers and more than one piece; otherwise once,
// over all of [0, count), on this thread. Pieces run concurrently, so they must not write the
// same data.
template <class Chunk>
void run_in_pieces(ThreadPool* pool, std::size_t count, std::size_t piece_size, const Chunk& chunk) {
  piece_size = std::max<std::size_t>(piece_size, 1);
  const std::size_t pieces = (count + piece_size - 1) / piece_size;
  if (pool == nullptr || pool->thread_count() == 1 || pieces <= 1) {
    chunk(std::size_t{0}, count);
    return;
  }
  pool->run(pieces,
            [&](std::size_t piece) { chunk(piece * piece_size, std::min(count, (piece + 1) * piece_size)); });
}

}  // namespace sg::ecs
