#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "ecs/parallel_pieces.h"

namespace sg::ecs {
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

// Sorted on a pool as by std::sort, for counts that leave a short last piece or an odd number
// of pieces to merge.
TEST(SortInPieces, SortsAsStdSortDoes) {
  ThreadPool threads(3);
  for (const std::size_t count : {0u, 1u, 63u, 64u, 65u, 1000u, 4099u}) {
    std::vector<std::uint64_t> items(count);
    std::mt19937_64 random(count);
    for (std::uint64_t& item : items) item = random() % 500;  // repeats too
    std::vector<std::uint64_t> expected = items;
    std::sort(expected.begin(), expected.end());
    std::vector<std::uint64_t> scratch;
    sort_in_pieces(&threads, items, scratch, 64, std::less<>());
    EXPECT_EQ(items, expected) << count << " items";
  }
}

}  // namespace
}  // namespace sg::ecs
