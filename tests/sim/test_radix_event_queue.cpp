#include "sim/radix_event_queue.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "sim/simulator.h"

namespace dvpr {
namespace {

using Entry = RadixEventQueue::Entry;
using Ref = std::set<std::pair<std::int64_t, std::uint64_t>>;  // independent reference order

Entry PopBoth(RadixEventQueue& q, Ref& ref) {
  const Entry e = q.Pop();
  EXPECT_FALSE(ref.empty());
  const auto expected = *ref.begin();
  ref.erase(ref.begin());
  EXPECT_EQ(e.time, expected.first);
  EXPECT_EQ(e.key, expected.second);
  return e;
}

TEST(RadixEventQueueTest, PopsInTimeThenKeyOrderAgainstASortedReference) {
  // The hold model with few distinct delays (many equal times) and a million-wide range.
  for (const std::int64_t max_delay : {std::int64_t{3}, std::int64_t{1'000'000}}) {
    std::mt19937_64 rng(42);
    std::uniform_int_distribution<std::int64_t> delay(0, max_delay);
    RadixEventQueue q;
    Ref ref;
    std::uint64_t key = 1;
    for (int i = 0; i < 500; ++i, ++key) {
      const std::int64_t t = delay(rng);
      q.Push({t, key});
      ref.insert({t, key});
    }
    for (int i = 0; i < 20000; ++i) {
      const Entry e = PopBoth(q, ref);
      const int pushes = static_cast<int>(rng() % 3);  // the pending set grows and shrinks
      for (int p = 0; p < pushes; ++p, ++key) {
        const std::int64_t t = e.time + delay(rng);
        q.Push({t, key});
        ref.insert({t, key});
      }
      if (q.empty()) break;
    }
    while (!q.empty()) PopBoth(q, ref);
    EXPECT_TRUE(ref.empty());
    EXPECT_EQ(q.size(), 0u);
  }
}

TEST(RadixEventQueueTest, EqualTimesPopFirstInFirstOutAcrossRefills) {
  // Entries at time 8 arrive before and after the queue moved to time 8 (bucket 0 refilled
  // from a higher bucket, then appended to): all come out by key.
  RadixEventQueue q;
  q.Push({8, 5});
  q.Push({1, 1});
  q.Push({8, 2});
  q.Push({12, 3});
  q.Push({8, 4});
  EXPECT_EQ(q.Pop().key, 1u);
  EXPECT_EQ(q.Top().time, 8);
  q.Push({8, 6});  // time == the current minimum, scheduled last
  std::vector<std::uint64_t> keys;
  while (!q.empty()) keys.push_back(q.Pop().key);
  EXPECT_EQ(keys, (std::vector<std::uint64_t>{2, 4, 5, 6, 3}));
}

TEST(RadixEventQueueTest, AnEntryBeforeThePeekedMinimumPopsFirst) {
  // Top() moved the queue to time 100; a push at 50 (a ScheduleAt after Run(until) stopped
  // before 100) must still come out first, and ties there keep key order.
  RadixEventQueue q;
  q.Push({100, 1});
  EXPECT_EQ(q.Top().time, 100);
  q.Push({50, 3});
  q.Push({50, 2});
  q.Push({70, 4});
  q.Push({100, 5});
  std::vector<std::pair<std::int64_t, std::uint64_t>> out;
  while (!q.empty()) {
    const Entry e = q.Pop();
    out.emplace_back(e.time, e.key);
  }
  EXPECT_EQ(out, (std::vector<std::pair<std::int64_t, std::uint64_t>>{{50, 2}, {50, 3}, {70, 4}, {100, 1}, {100, 5}}));
}

TEST(RadixEventQueueTest, LargeTimesUseTheHighBuckets) {
  RadixEventQueue q;
  const std::int64_t big = std::int64_t{1} << 62;
  q.Push({big, 1});
  q.Push({3, 2});
  q.Push({big - 1, 3});
  EXPECT_EQ(q.Pop().time, 3);
  EXPECT_EQ(q.Pop().time, big - 1);
  EXPECT_EQ(q.Pop().time, big);
  EXPECT_TRUE(q.empty());
}

TEST(RadixEventQueueTest, ManyPendingEntriesAcrossAllLevelsMatchASortedReference) {
  // 20 000 pending entries, delays from 0 (same time as the popped one) to 2^40 ns, so entries
  // sit on every level of the wheel and in near_, with many equal times from the small delays.
  std::mt19937_64 rng(11);
  RadixEventQueue q;
  Ref ref;
  std::uint64_t key = 1;
  auto delay = [&rng]() -> std::int64_t {
    const int bits = static_cast<int>(rng() % 41);  // 0..40: log-uniform magnitudes
    return static_cast<std::int64_t>(rng() & ((std::uint64_t{1} << bits) - 1));
  };
  for (int i = 0; i < 20000; ++i, ++key) {
    const std::int64_t t = delay();
    q.Push({t, key});
    ref.insert({t, key});
  }
  for (int i = 0; i < 200000; ++i, ++key) {
    const Entry e = PopBoth(q, ref);
    const std::int64_t t = e.time + delay();
    q.Push({t, key});
    ref.insert({t, key});
  }
  while (!q.empty()) PopBoth(q, ref);
  EXPECT_TRUE(ref.empty());
}

TEST(RadixEventQueueTest, ABlockOfManyEqualAndNearTimesKeepsKeyOrder) {
  // 5000 entries in one 256 ns block (counting sort) and 10 in another (insertion sort), with
  // pushes into the block being drained and before it after a peek: (time, key) order throughout.
  RadixEventQueue q;
  Ref ref;
  std::uint64_t key = 1;
  std::mt19937_64 rng(5);
  for (int i = 0; i < 5000; ++i, ++key) {
    const std::int64_t t = 1024 + static_cast<std::int64_t>(rng() % 7) * 30;
    q.Push({t, key});
    ref.insert({t, key});
  }
  for (int i = 0; i < 10; ++i, ++key) {
    q.Push({4096 + 200 - 20 * i, key});
    ref.insert({4096 + 200 - 20 * i, key});
  }
  for (int i = 0; i < 2000; ++i) PopBoth(q, ref);
  for (int i = 0; i < 100; ++i, ++key) {  // into the block being drained, at and after its head
    const std::int64_t t = q.Top().time + static_cast<std::int64_t>(rng() % 3) * 30;
    q.Push({t, key});
    ref.insert({t, key});
  }
  while (!q.empty()) PopBoth(q, ref);
  EXPECT_TRUE(ref.empty());
}

TEST(SimulatorQueueTest, HoldModelWithCancelsAndRunUntilMatchesASortedReference) {
  // Every event reschedules one or two at random delays (many equal times) and cancels a random
  // pending one now and then; the run is cut by Run(until) at random points, after which events
  // are scheduled before the already-peeked next one. The reference is a std::set of
  // (time, sequence) pending pairs: each event that runs must be its first element.
  Simulator sim;
  std::mt19937_64 rng(3);
  std::set<std::pair<std::int64_t, int>> pending;
  std::vector<std::pair<EventId, std::pair<std::int64_t, int>>> ids;
  int seq = 0;
  int ran = 0;
  std::function<void(std::int64_t)> schedule = [&](std::int64_t t) {
    const int s = seq++;
    const EventId id = sim.ScheduleAt(SimTime::Nanos(t), [&, t, s] {
      ASSERT_FALSE(pending.empty());
      EXPECT_EQ(*pending.begin(), std::make_pair(t, s));
      pending.erase(pending.begin());
      ++ran;
      if (seq < 60000) {
        for (int k = 0; k < 1 + static_cast<int>(rng() % 2); ++k) schedule(t + static_cast<std::int64_t>(rng() % 4) * static_cast<std::int64_t>(rng() % 3000));
      }
      if (rng() % 8 == 0 && !ids.empty()) {
        const auto [victim, when] = ids[rng() % ids.size()];
        EXPECT_EQ(sim.Cancel(victim), pending.erase(when) == 1);
      }
    });
    pending.insert({t, s});
    ids.emplace_back(id, std::make_pair(t, s));
  };
  for (int i = 0; i < 500; ++i) schedule(static_cast<std::int64_t>(rng() % 100000));
  while (sim.PendingEvents() > 0) {
    sim.Run(sim.Now() + SimTime::Nanos(static_cast<std::int64_t>(rng() % 20000)));
    if (rng() % 2 == 0) schedule(sim.Now().ns() + static_cast<std::int64_t>(rng() % 50));
    EXPECT_EQ(sim.PendingEvents(), pending.size());
  }
  EXPECT_TRUE(pending.empty());
  EXPECT_GT(ran, 50000);
}

TEST(SimulatorQueueTest, ScheduleAfterRunUntilBeforeAPeekedEventRunsInOrder) {
  Simulator sim;
  std::vector<int> order;
  sim.Schedule(SimTime::Millis(10), [&] { order.push_back(10); });
  sim.Run(SimTime::Millis(4));  // peeks at 10 ms and stops
  sim.ScheduleAt(SimTime::Millis(6), [&] { order.push_back(6); });
  sim.ScheduleAt(SimTime::Millis(5), [&] { order.push_back(5); });
  sim.ScheduleAt(SimTime::Millis(10), [&] { order.push_back(11); });  // same time, later
  sim.Run();
  EXPECT_EQ(order, (std::vector<int>{5, 6, 10, 11}));
}

TEST(SimulatorQueueTest, CancellationAmongManyPendingEvents) {
  // Half of 10^5 pending events cancelled; the rest run in time-then-FIFO order.
  Simulator sim;
  std::mt19937_64 rng(7);
  std::vector<EventId> ids;
  std::vector<std::pair<std::int64_t, int>> ran;
  std::vector<std::pair<std::int64_t, int>> expected;
  constexpr int kEvents = 100'000;
  ids.reserve(kEvents);
  for (int i = 0; i < kEvents; ++i) {
    const std::int64_t t = static_cast<std::int64_t>(rng() % 50'000);
    ids.push_back(sim.Schedule(SimTime::Nanos(t), [&ran, t, i] { ran.emplace_back(t, i); }));
    if (i % 2 == 1) expected.emplace_back(t, i);
  }
  for (int i = 0; i < kEvents; i += 2) EXPECT_TRUE(sim.Cancel(ids[static_cast<std::size_t>(i)]));
  EXPECT_EQ(sim.PendingEvents(), static_cast<std::size_t>(kEvents / 2));
  sim.Run();
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(ran, expected);
}

}  // namespace
}  // namespace dvpr
