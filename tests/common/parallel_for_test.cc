// ParallelFor: every item runs once whatever the thread count, items go to threads in a fixed
// pattern, and an error is rethrown (the lowest item's) after every item has run.

#include "hotlap/common/parallel_for.h"

#include <atomic>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace hotlap {
namespace {

TEST(ParallelFor, RunsEveryItemOnceOnAnyThreadCount) {
  for (int threads : {-1, 0, 1, 2, 3, 8, 100}) {
    std::vector<std::atomic<int>> runs(17);
    ParallelFor(runs.size(), threads, [&](size_t i) { ++runs[i]; });
    for (size_t i = 0; i < runs.size(); ++i) {
      EXPECT_EQ(runs[i].load(), 1) << "item " << i << " on " << threads << " threads";
    }
  }
  ParallelFor(0, 4, [](size_t) { FAIL() << "no item to run"; });
}

TEST(ParallelFor, UsesAtMostTheThreadsAskedForAndItemsShareThemInTurn) {
  std::vector<std::thread::id> ids(6);
  ParallelFor(ids.size(), 2, [&](size_t i) { ids[i] = std::this_thread::get_id(); });
  EXPECT_EQ(std::set<std::thread::id>(ids.begin(), ids.end()).size(), 2u);
  for (size_t i = 2; i < ids.size(); ++i) EXPECT_EQ(ids[i], ids[i - 2]) << "item " << i;
  EXPECT_NE(ids[0], ids[1]);
}

TEST(ParallelFor, RethrowsTheLowestItemsErrorAfterRunningEveryItem) {
  std::vector<std::atomic<int>> runs(10);
  try {
    ParallelFor(runs.size(), 3, [&](size_t i) {
      ++runs[i];
      if (i == 7 || i == 4) throw std::runtime_error("item " + std::to_string(i));
    });
    FAIL() << "no error rethrown";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "item 4");
  }
  for (size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].load(), 1) << "item " << i;
}

}  // namespace
}  // namespace hotlap
