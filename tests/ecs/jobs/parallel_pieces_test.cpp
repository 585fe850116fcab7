// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "ecs/jobs/parallel_pieces.h"

namespace sg::jobs {
namespace {

// The kept indices come out ranked in index order, on a pool as on one thread, with pieces that
// keep none, some and all of theirs.
TEST(KeepInPieces, RanksTheKeptIndicesInOrderOnAPoolAsSerially) {
  const auto keep = [](std::size_t i) { return i % 3 == 0 || (i >= 200 && i < 300) || i >= 900; };
  KeepScratch scratch;  // shared by both calls, as a frame's callers share theirs
  const auto filter = [&](ThreadPool* pool) {
    std::vector<std::size_t> kept(1000, SIZE_MAX);
    const std::size_t count = keep_in_pieces(pool, kept.size(), 64, scratch, keep,
                                             [&](std::size_t i, std::size_t rank) { kept[rank] = i; });
    kept.resize(count);
    return kept;
  };
  std::vector<std::size_t> expected;
  for (std::size_t i = 0; i < 1000; ++i) {
    if (keep(i)) expected.push_back(i);
  }
  ThreadPool threads(3);
  EXPECT_EQ(filter(nullptr), expected);
  EXPECT_EQ(filter(&threads), expected);
}

}  // namespace
}  // namespace sg::jobs
