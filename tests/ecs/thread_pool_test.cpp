#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "ecs/thread_pool.h"

namespace sg::ecs {
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
}  // namespace sg::ecs
