// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace sg::jobs {

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
//   thread can take longer than its share of a batch. The caller, once out of tasks, waits for
//   the batch's last ones the same way.
// - count must be below 2^32 (else std::length_error, before any task runs).
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
  using Task = std::function<void(std::size_t)>;

  void work();
  // Claims and runs tasks of batch number `batch` until none are left or another batch began.
  void drain(std::uint32_t batch);
  // Wakes sleeping workers: they re-read claim_ and spin for a while.
  void signal_workers();

  // Tasks are claimed without a lock, one compare-exchange a claim (of one task or several, in
  // order) on this word: the batch number in the high half, the count of tasks not yet claimed in
  // the low half. Whether a task is left is
  // read from this word alone. Read from count_, as it once was, a worker waking late could see
  // the next batch's count_ beside the last batch's word, claim a task that did not exist, and
  // drive unfinished_ below zero, so that the caller slept forever. A mutex per claim cost more
  // than the tasks of a short batch once a dozen threads contended for it.
  std::atomic<std::uint64_t> claim_{0};
  // The current batch's tasks; written before claim_ announces the batch. A claim that succeeds
  // proves its batch still runs, and its task keeps the batch running until it returns, so these
  // are that batch's when the claimer reads them after the claim.
  std::atomic<const Task*> task_{nullptr};
  std::atomic<std::uint32_t> count_{0};
  std::atomic<std::uint32_t> unfinished_{0};  // tasks of the batch not returned yet
  std::atomic<std::uint32_t> signals_{0};     // bumped by each batch and wake(); sleepers wait on it
  std::mutex error_mutex_;
  std::exception_ptr error_;  // the batch's first exception
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

// How many pieces of `piece_size` cover `count` entries, at least one: the size of the tallies
// a caller of run_in_pieces keeps per piece (a piece's begin / piece_size indexes them).
inline std::size_t piece_count(std::size_t count, std::size_t piece_size) {
  return std::max<std::size_t>((count + piece_size - 1) / piece_size, 1);
}

}  // namespace sg::jobs
