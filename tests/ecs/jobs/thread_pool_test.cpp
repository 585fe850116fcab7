// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "ecs/jobs/thread_pool.h"

namespace sg::jobs {
namespace {

TEST(ThreadPool, RunsEveryTaskOnceInEveryBatch) {
  ThreadPool threads(3);
  EXPECT_EQ(threads.thread_count(), 4u);
  // Many short batches: a worker waking late must never run a task of a finished batch.
  for (int batch = 0; batch < 200; ++batch) {
    std::vector<std::atomic<int>> runs(37);
    threads.run(runs.size(), [&](std::size_t task) { runs[task].fetch_add(1); });
    for (const std::atomic<int>& count : runs) ASSERT_EQ(count.load(), 1) << "batch " << batch;
  }
}

// A worker that wakes late, while the caller announces the next and larger batch, must find no
// task of the finished batch left. Once it could: it ran a task twice, the batch's count of
// unfinished tasks wrapped below zero, and the caller slept forever. Many workers sharing few
// cores and batches alternating between small and large make that moment likely enough that
// the old pool failed about half the runs of this test (2 cores); a watchdog turns a hang into a failure.
TEST(ThreadPool, LateWorkersNeverClaimATaskOfAFinishedBatch) {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::thread watchdog([&] {
    std::unique_lock lock(mutex);
    if (!finished.wait_for(lock, std::chrono::minutes(2), [&] { return done; })) {
      std::fprintf(stderr, "ThreadPool hung: a batch never finished\n");
      std::abort();
    }
  });
  const auto first_problem = [] {
    ThreadPool threads(15);
    std::vector<std::atomic<int>> runs(24);
    for (int batch = 0; batch < 4'000'000; ++batch) {
      const std::size_t count = batch % 2 == 1 ? runs.size() : 1 + batch / 2 % 4;
      for (std::size_t task = 0; task < count; ++task) runs[task].store(0, std::memory_order_relaxed);
      std::atomic<bool> out_of_range{false};
      threads.run(count, [&](std::size_t task) {
        if (task < count) {
          runs[task].fetch_add(1, std::memory_order_relaxed);
        } else {
          out_of_range = true;
        }
      });
      if (out_of_range) return "a task index past the batch's count in batch " + std::to_string(batch);
      for (std::size_t task = 0; task < count; ++task) {
        if (runs[task].load() != 1)
          return "task " + std::to_string(task) + " of batch " + std::to_string(batch) + " ran " +
                 std::to_string(runs[task].load()) + " times";
      }
    }
    return std::string();
  };
  const std::string problem = first_problem();
  {
    const std::lock_guard lock(mutex);
    done = true;
  }
  finished.notify_one();
  watchdog.join();
  EXPECT_EQ(problem, "");
}

// wake() is only a hint: batches after it, before it, with or without a pause (workers asleep
// again), and a pool destroyed right after one, all behave as without it.
TEST(ThreadPool, WakeBeforeABatchChangesNothingButTiming) {
  ThreadPool threads(3);
  for (int round = 0; round < 50; ++round) {
    threads.wake();
    if (round % 10 == 0) std::this_thread::sleep_for(2 * ThreadPool::spin_time);
    std::vector<std::atomic<int>> runs(29);
    threads.run(runs.size(), [&](std::size_t task) { runs[task].fetch_add(1); });
    for (const std::atomic<int>& count : runs) ASSERT_EQ(count.load(), 1) << "round " << round;
  }
  ThreadPool woken_then_gone(2);
  woken_then_gone.wake();
  ThreadPool without_workers(0);
  without_workers.wake();
}

TEST(ThreadPool, RefusesBatchesOfAsManyTasksAsTheClaimCounterHolds) {
  ThreadPool threads(1);
  bool ran = false;
  EXPECT_THROW(threads.run(std::size_t{1} << 32, [&](std::size_t) { ran = true; }), std::length_error);
  EXPECT_FALSE(ran);
}

TEST(ThreadPool, WithoutWorkersRunsOnTheCaller) {
  ThreadPool threads(0);
  int sum = 0;
  threads.run(4, [&](std::size_t task) { sum += static_cast<int>(task); });
  EXPECT_EQ(sum, 6);
}

TEST(ThreadPool, RethrowsATasksExceptionAfterTheOthersRan) {
  ThreadPool threads(2);
  std::atomic<int> ran{0};
  EXPECT_THROW(threads.run(10,
                           [&](std::size_t task) {
                             ran.fetch_add(1);
                             if (task == 3) throw std::runtime_error("task 3");
                           }),
               std::runtime_error);
  EXPECT_EQ(ran.load(), 10);
  threads.run(1, [&](std::size_t) { ran.fetch_add(1); });  // still usable
  EXPECT_EQ(ran.load(), 11);
}

}  // namespace
}  // namespace sg::jobs
