#include "sim/simulator.h"

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace dvpr {
namespace {

class SimulatorTest : public ::testing::Test {
 protected:
  Simulator sim;
  std::vector<int> order;
  auto Record(int tag) {
    return [this, tag] { order.push_back(tag); };
  }
};

TEST_F(SimulatorTest, RunsInTimeOrder) {
  sim.Schedule(SimTime::Millis(3), Record(3));
  sim.Schedule(SimTime::Millis(1), Record(1));
  sim.Schedule(SimTime::Millis(2), Record(2));
  sim.Run();
  EXPECT_EQ(order, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(sim.Now(), SimTime::Millis(3));
  EXPECT_EQ(sim.EventsExecuted(), 3u);
  EXPECT_EQ(sim.PendingEvents(), 0u);
}

TEST_F(SimulatorTest, EqualTimesRunFirstInFirstOut) {
  for (int i = 0; i < 1000; ++i) sim.Schedule(SimTime::Micros(7), Record(i));
  sim.Run();
  ASSERT_EQ(order.size(), 1000u);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(order[i], i);
}

TEST_F(SimulatorTest, EqualTimeEventsScheduledFromAnEventRunAfterEarlierOnes) {
  sim.Schedule(SimTime::Zero(), [this] {
    order.push_back(0);
    sim.Schedule(SimTime::Zero(), Record(2));  // same time, scheduled later
  });
  sim.Schedule(SimTime::Zero(), Record(1));
  sim.Run();
  EXPECT_EQ(order, (std::vector<int>{0, 1, 2}));
}

TEST_F(SimulatorTest, CancelledEventNeverRuns) {
  const EventId a = sim.Schedule(SimTime::Millis(1), Record(1));
  sim.Schedule(SimTime::Millis(2), Record(2));
  EXPECT_TRUE(sim.Cancel(a));
  EXPECT_FALSE(sim.Cancel(a));  // twice
  EXPECT_EQ(sim.PendingEvents(), 1u);
  sim.Run();
  EXPECT_EQ(order, (std::vector<int>{2}));
  EXPECT_EQ(sim.EventsExecuted(), 1u);
}

TEST_F(SimulatorTest, CancelAfterRunOrOfReusedSlotIsRefused) {
  const EventId a = sim.Schedule(SimTime::Millis(1), Record(1));
  sim.Run();
  // The slot of `a` is reused by `b`; cancelling `a` must not cancel `b`.
  sim.Schedule(SimTime::Millis(1), Record(2));
  EXPECT_FALSE(sim.Cancel(a));
  EXPECT_FALSE(sim.Cancel(EventId()));
  sim.Run();
  EXPECT_EQ(order, (std::vector<int>{1, 2}));
}

TEST_F(SimulatorTest, AnEventCanCancelALaterOne) {
  EventId later;
  sim.Schedule(SimTime::Millis(1), [&] { EXPECT_TRUE(sim.Cancel(later)); });
  later = sim.Schedule(SimTime::Millis(2), Record(2));
  sim.Run();
  EXPECT_TRUE(order.empty());
}

TEST_F(SimulatorTest, RunningEventCannotCancelItself) {
  EventId self;
  self = sim.Schedule(SimTime::Millis(1), [&] { EXPECT_FALSE(sim.Cancel(self)); order.push_back(1); });
  sim.Run();
  EXPECT_EQ(order, (std::vector<int>{1}));
}

TEST_F(SimulatorTest, RunUntilStopsAtTheBoundaryInclusiveAndAdvancesTheClock) {
  sim.Schedule(SimTime::Millis(5), Record(5));
  sim.Schedule(SimTime::Millis(10), Record(10));
  sim.Schedule(SimTime::Millis(11), Record(11));
  sim.Run(SimTime::Millis(10));
  EXPECT_EQ(order, (std::vector<int>{5, 10}));
  sim.Run(SimTime::Millis(10) + SimTime::Nanos(500));
  EXPECT_EQ(sim.Now(), SimTime::Millis(10) + SimTime::Nanos(500));
  sim.ScheduleAt(SimTime::Millis(11), Record(12));  // same time as the pending event, scheduled later
  sim.Run();
  EXPECT_EQ(order, (std::vector<int>{5, 10, 11, 12}));
}

TEST_F(SimulatorTest, StopReturnsAfterTheCurrentEvent) {
  sim.Schedule(SimTime::Millis(1), [&] { order.push_back(1); sim.Stop(); });
  sim.Schedule(SimTime::Millis(2), Record(2));
  sim.Run();
  EXPECT_EQ(order, (std::vector<int>{1}));
  sim.Run();
  EXPECT_EQ(order, (std::vector<int>{1, 2}));
}

TEST_F(SimulatorTest, RejectsNegativeDelayAndThePast) {
  sim.Schedule(SimTime::Millis(2), [] {});
  sim.Run();
  EXPECT_THROW(sim.Schedule(SimTime::Nanos(-1), [] {}), std::invalid_argument);
  EXPECT_THROW(sim.ScheduleAt(SimTime::Millis(1), [] {}), std::invalid_argument);
}

TEST_F(SimulatorTest, LargeCapturesAndNonTrivialCallablesWork) {
  auto shared = std::make_shared<int>(0);
  std::vector<int> big(100, 1);
  {
    std::function<void()> f = [shared] { ++*shared; };
    sim.Schedule(SimTime::Zero(), std::move(f));
  }
  sim.Schedule(SimTime::Zero(), [shared, big, pad = std::string(100, 'x')] { *shared += big[99] + 10; });
  const EventId cancelled = sim.Schedule(SimTime::Zero(), [shared] { *shared += 1000; });
  sim.Cancel(cancelled);
  sim.Run();
  EXPECT_EQ(*shared, 12);
  EXPECT_EQ(shared.use_count(), 1);  // every captured copy was destroyed
}

TEST_F(SimulatorTest, ManyInterleavedEventsKeepTimeThenFifoOrder) {
  // Times 0..9 ms, each scheduled 300 times in an interleaved order; the
  // run must be sorted by time and, within a time, by scheduling order.
  std::vector<std::pair<int, int>> seen;
  int seq = 0;
  for (int round = 0; round < 300; ++round) {
    for (int t : {7, 2, 9, 0, 4, 1, 8, 3, 6, 5}) {
      const int s = seq++;
      sim.Schedule(SimTime::Millis(t), [&seen, t, s] { seen.emplace_back(t, s); });
    }
  }
  sim.Run();
  ASSERT_EQ(seen.size(), 3000u);
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_LT(seen[i - 1], seen[i]);
}

TEST_F(SimulatorTest, ExceptionFromAnEventPropagatesAndTheSimulatorStaysUsable) {
  sim.Schedule(SimTime::Millis(1), [] { throw std::runtime_error("boom"); });
  sim.Schedule(SimTime::Millis(2), Record(2));
  EXPECT_THROW(sim.Run(), std::runtime_error);
  sim.Run();
  EXPECT_EQ(order, (std::vector<int>{2}));
}

}  // namespace
}  // namespace dvpr
