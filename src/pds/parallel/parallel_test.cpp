#include "pds/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <numeric>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

namespace pds {
namespace {

// Every index in [begin, end) is visited exactly once, in chunks of at most
// the grain, whatever the thread count.
TEST(ParallelFor, CoversTheRangeOnceInChunksOfAtMostTheGrain) {
  for (int threads : {0, 1, 2, 3, 8})
    for (std::size_t grain : {1, 7, 64, 1000})
      for (auto [begin, end] : {std::pair<std::size_t, std::size_t>{0, 0}, {5, 6}, {3, 1000}, {0, 4096}}) {
        std::vector<std::atomic<int>> hits(end + 1);
        std::atomic<bool> oversized{false};
        parallel_for(begin, end, grain, threads, [&](std::size_t b, std::size_t e) {
          if (e - b > grain || b >= e) oversized = true;
          for (std::size_t i = b; i < e; ++i) ++hits[i];
        });
        EXPECT_FALSE(oversized);
        for (std::size_t i = 0; i <= end; ++i)
          ASSERT_EQ(hits[i].load(), i >= begin && i < end ? 1 : 0)
              << "index " << i << ", threads " << threads << ", grain " << grain;
      }
}

TEST(ParallelFor, UsesSeveralThreadsWhenAskedAndOneWhenLimited) {
  auto threads_seen = [](int threads) {
    std::mutex mutex;
    std::set<std::thread::id> ids;
    parallel_for(0, 64, 1, threads, [&](std::size_t, std::size_t) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      std::lock_guard<std::mutex> lock(mutex);
      ids.insert(std::this_thread::get_id());
    });
    return ids.size();
  };
  EXPECT_EQ(threads_seen(1), 1u);
  EXPECT_GE(threads_seen(2), 2u);
  {
    ThreadLimit limit(1);
    EXPECT_EQ(threads_seen(4), 1u);
  }
  EXPECT_GE(threads_seen(4), 2u);
}

TEST(ParallelFor, RethrowsTheBodysExceptionAndStaysUsable) {
  EXPECT_THROW(parallel_for(0, 1000, 1, 4,
                            [](std::size_t b, std::size_t) {
                              if (b == 500) throw std::runtime_error("chunk 500");
                            }),
               std::runtime_error);
  std::atomic<std::size_t> sum{0};
  parallel_for(0, 1000, 10, 4, [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) sum += i;
  });
  EXPECT_EQ(sum.load(), 999u * 1000u / 2u);
}

// A loop inside a body runs on that thread; loops from several user threads
// at once all complete.
TEST(ParallelFor, NestedAndConcurrentLoopsComplete) {
  std::atomic<std::size_t> count{0};
  parallel_for(0, 16, 1, 4, [&](std::size_t, std::size_t) {
    parallel_for(0, 100, 3, 4, [&](std::size_t b, std::size_t e) { count += e - b; });
  });
  EXPECT_EQ(count.load(), 1600u);
  count = 0;
  std::vector<std::thread> users;
  for (int t = 0; t < 4; ++t)
    users.emplace_back([&] {
      for (int k = 0; k < 50; ++k) parallel_for(0, 200, 7, 3, [&](std::size_t b, std::size_t e) { count += e - b; });
    });
  for (auto& u : users) u.join();
  EXPECT_EQ(count.load(), 4u * 50u * 200u);
}

}  // namespace
}  // namespace pds
