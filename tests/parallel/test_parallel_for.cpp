// The thread pool (ParallelFor) and its in-order consumer (ParallelForInOrder): every index
// once, errors rethrown, consumption in index order however the values finish.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/domain/parallel/parallel_for.h"
#include "experiments/domain/parallel/parallel_for_in_order.h"

namespace dvpr {
namespace {

TEST(ParallelFor, RunsEveryIndexOnceForAnyThreadCount) {
  for (int threads : {0, 1, 2, 5}) {
    std::vector<std::atomic<int>> runs(100);
    std::atomic<std::int64_t> sum{0};
    ParallelFor(100, threads, [&](std::int64_t i) {
      ++runs[static_cast<std::size_t>(i)];
      sum += i;
    });
    for (const auto& r : runs) EXPECT_EQ(r.load(), 1) << threads << " threads";
    EXPECT_EQ(sum.load(), 4950) << threads << " threads";  // 0 + 1 + ... + 99
  }
}

TEST(ParallelFor, RethrowsTheErrorAndOnOneThreadRunsNothingAfterIt) {
  std::vector<std::int64_t> ran;
  EXPECT_THROW(ParallelFor(10, 1,
                           [&](std::int64_t i) {
                             ran.push_back(i);
                             if (i == 3) throw std::runtime_error("index 3");
                           }),
               std::runtime_error);
  EXPECT_EQ(ran, (std::vector<std::int64_t>{0, 1, 2, 3}));
  try {
    ParallelFor(50, 3, [](std::int64_t i) {
      if (i == 7) throw std::runtime_error("index 7");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "index 7");
  }
}

// The system refuses the second worker thread (EAGAIN, as pthread_create does at RLIMIT_NPROC):
// the one started is joined, nothing aborts, and the error is one line (before: std::terminate
// on a vector of joinable threads). Of 4 workers, the calling thread and one more had started.
TEST(ParallelFor, AThreadTheSystemRefusesIsOneErrorAfterTheStartedOnesJoined) {
  int starts = 0;
  const auto start_one_then_refuse = [&](std::vector<std::thread>& pool, auto& work) {
    if (++starts == 2) throw std::system_error(std::make_error_code(std::errc::resource_unavailable_try_again));
    pool.emplace_back(std::ref(work));
  };
  std::atomic<int> ran{0};
  try {
    ParallelFor(1000, 4, [&](std::int64_t) { ++ran; }, start_one_then_refuse);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot start threads: " + std::make_error_code(std::errc::resource_unavailable_try_again).message() +
                  " (started 2 of 4; a process or thread limit is reached: try --threads 1)");
  }
  EXPECT_EQ(starts, 2);
  EXPECT_LE(ran.load(), 1000);  // what the started worker took before it was stopped, each once
}

// Value 0 is held back until values 1-5 are done (two threads: one waits on 0, the other does
// the rest), so 1-5 finish first; they must still be consumed after 0, in order.
TEST(ParallelForInOrder, ConsumesInIndexOrderWhenValuesFinishOutOfOrder) {
  std::mutex mutex;
  std::condition_variable others_done;
  int produced = 0;
  std::vector<std::int64_t> order;
  std::vector<int> produced_at_consume;
  ParallelForInOrder(
      6, 2,
      [&](std::int64_t i) {
        std::unique_lock lock(mutex);
        if (i == 0) others_done.wait(lock, [&] { return produced == 5; });
        ++produced;
        others_done.notify_all();
        return i * i;
      },
      [&](std::int64_t i, std::int64_t&& square) {
        EXPECT_EQ(square, i * i);
        order.push_back(i);
        const std::lock_guard lock(mutex);
        produced_at_consume.push_back(produced);
      });
  EXPECT_EQ(order, (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(produced_at_consume.front(), 6);  // 0 was consumed only once it was done, after 1-5
}

TEST(ParallelForInOrder, NothingIsConsumedAfterAFailedConsume) {
  for (int threads : {1, 3}) {
    std::vector<std::int64_t> consumed;
    EXPECT_THROW(ParallelForInOrder(
                     40, threads, [](std::int64_t i) { return i; },
                     [&](std::int64_t i, std::int64_t&&) {
                       if (i == 2) throw std::runtime_error("consume 2");
                       consumed.push_back(i);
                     }),
                 std::runtime_error);
    EXPECT_EQ(consumed, (std::vector<std::int64_t>{0, 1})) << threads << " threads";
  }
}

TEST(ParallelForInOrder, AFailedValueEndsTheConsumptionBeforeIt) {
  for (int threads : {1, 3}) {
    std::vector<std::int64_t> consumed;
    EXPECT_THROW(ParallelForInOrder(
                     40, threads,
                     [](std::int64_t i) {
                       if (i == 5) throw std::runtime_error("value 5");
                       return i;
                     },
                     [&](std::int64_t i, std::int64_t&&) { consumed.push_back(i); }),
                 std::runtime_error);
    // Values 0-4 were handed out before 5, so they finish and are consumed; none after 5 is.
    EXPECT_EQ(consumed, (std::vector<std::int64_t>{0, 1, 2, 3, 4})) << threads << " threads";
  }
}

}  // namespace
}  // namespace dvpr
