#include "agents/messages/sim_transport.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "agents/messages/channels.h"
#include "net_models/medium/point_to_point_link.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

// Three robots on 1 Mbit/s, 5 ms point-to-point links.
//  query_t with 128 floats: 8 + 8 + 2 + 4 + 8 + 2 + 512 = 544 bytes; on
//  "DVPR_QUERY_ALL" (14 chars): UDP 8 + 15 + 544 = 567, frame 567 + 28 + 2 = 597
//  bytes = 4776 bits -> 4.776 ms + 5 ms = 9.776 ms.
//  match_t: 8 + 8 + 2 + 4 + 2 + 1 + 2 + 4 + 4 = 35 bytes; on "DVPR_MATCH_0"
//  (12 chars): UDP 8 + 13 + 35 = 56, frame 86 bytes -> 0.688 ms + 5 ms = 5.688 ms.
constexpr SimTime kQueryArrival = SimTime::Micros(9776);
constexpr SimTime kMatchArrival = SimTime::Micros(9776 + 5688);

class SimTransportTest : public ::testing::Test {
 protected:
  static constexpr int kRobots = 3;
  Simulator sim;
  Network net{sim, kRobots, std::make_unique<PointToPointLink>(
                                PointToPointParams{DataRate::Mbps(1), SimTime::Millis(5), 100, {}}, kRobots)};
  std::vector<std::unique_ptr<SimTransport>> robots;

  void SetUp() override {
    for (int r = 0; r < kRobots; ++r) robots.push_back(std::make_unique<SimTransport>(net, NodeId(r)));
  }
  static query_t Query(int robot, int frame) {
    query_t q{};
    q.utime = 0;
    q.robot = static_cast<std::int16_t>(robot);
    q.frame = frame;
    q.dim = 128;
    q.descriptor.assign(128, 0.25f);
    return q;
  }
  // Robots 1..n-1 answer every broadcast query with a match_t to the sender.
  std::vector<Subscription> Responders() {
    std::vector<Subscription> subs;
    for (int r = 1; r < kRobots; ++r) {
      SimTransport* t = robots[r].get();
      subs.push_back(t->Subscribe<query_t>(channels::kQueryAll, [t, r](const query_t& q) {
        match_t m{};
        m.utime = t->Now().us();
        m.query_robot = q.robot;
        m.query_frame = q.frame;
        m.responder = static_cast<std::int16_t>(r);
        t->Publish(channels::Match(RobotId(q.robot)), m);
      }));
    }
    return subs;
  }
};

TEST_F(SimTransportTest, QueryAndRepliesArriveAtHandWorkedTimes) {
  auto responders = Responders();
  std::vector<std::pair<SimTime, int>> matches;
  auto sub = robots[0]->Subscribe<match_t>(channels::Match(RobotId(0)), [&](const match_t& m) {
    matches.emplace_back(robots[0]->Now(), m.responder);
  });
  EXPECT_EQ(robots[0]->Publish(channels::kQueryAll, Query(0, 17)), 544u);
  sim.Run();
  ASSERT_EQ(matches.size(), 2u);
  EXPECT_EQ(matches[0], std::make_pair(kMatchArrival, 1));
  EXPECT_EQ(matches[1], std::make_pair(kMatchArrival, 2));
  EXPECT_EQ(net.Counters(NodeId(0), NodeId(1)).wire_bytes, 597);
  EXPECT_EQ(net.Counters(NodeId(2), NodeId(0)).wire_bytes, 86);
}

// The same exchange with the query and the replies on interned channels: the same times and
// bytes (the channel's name, 14 and 12 characters, is still counted on the wire).
TEST_F(SimTransportTest, InternedChannelsCarryTheSameMessagesAsNamedOnes) {
  std::vector<Subscription> subs;
  for (int r = 1; r < kRobots; ++r) {
    SimTransport* t = robots[r].get();
    const PublishChannel reply = t->Intern(channels::Match(RobotId(0)));
    subs.push_back(t->Subscribe<query_t>(channels::kQueryAll, [t, r, reply](const query_t& q) {
      match_t m{};
      m.query_robot = q.robot;
      m.responder = static_cast<std::int16_t>(r);
      t->Publish(reply, m);
    }));
  }
  std::vector<std::pair<SimTime, int>> matches;
  subs.push_back(robots[0]->Subscribe<match_t>(channels::Match(RobotId(0)), [&](const match_t& m) {
    matches.emplace_back(robots[0]->Now(), m.responder);
  }));
  const PublishChannel all = robots[0]->Intern(channels::kQueryAll);
  EXPECT_EQ(robots[0]->Publish(all, Query(0, 17)), 544u);
  sim.Run();
  EXPECT_EQ(matches, (std::vector<std::pair<SimTime, int>>{{kMatchArrival, 1}, {kMatchArrival, 2}}));
  EXPECT_EQ(net.Counters(NodeId(0), NodeId(1)).wire_bytes, 597);
  EXPECT_EQ(net.Counters(NodeId(2), NodeId(0)).wire_bytes, 86);
  EXPECT_EQ(net.Counters(NodeId(2), NodeId(0)).delivered, 1u);
}

// The agents of one network share its channel table: a name interned by two robots is one
// value, named as it was interned, and a name interned before anyone subscribes still reaches
// a later subscriber.
TEST_F(SimTransportTest, TransportsOfOneNetworkInternANameAlike) {
  const PublishChannel by_1 = robots[1]->Intern("DVPR_X");
  const PublishChannel by_2 = robots[2]->Intern("DVPR_X");
  EXPECT_EQ(by_1, by_2);
  EXPECT_NE(robots[1]->Intern("DVPR_Y"), by_1);
  EXPECT_EQ(robots[2]->NameOf(by_1), "DVPR_X");
  std::vector<int> frames;
  const Subscription sub = robots[0]->Subscribe<query_t>("DVPR_X", [&](const query_t& q) { frames.push_back(q.frame); });
  robots[1]->Publish(by_1, Query(1, 4));
  robots[2]->Publish(by_2, Query(2, 5));
  sim.Run();
  EXPECT_EQ(frames, (std::vector<int>{4, 5}));
}

// Robots that share their decoded messages (as a simulation's do) see one decoded query per
// broadcast: both receivers of the first query get the same message, kept alive by the first
// receiver's reference while the second query is decoded into another one, intact.
TEST_F(SimTransportTest, ReceiversOfOneBroadcastShareItsDecodedMessage) {
  DecodedMessages shared;
  for (auto& r : robots) r->ShareDecodes(&shared);
  std::vector<MessageRef<query_t>> kept;
  std::vector<Subscription> subs;
  for (int r = 1; r < kRobots; ++r) {
    subs.push_back(robots[r]->SubscribeShared<query_t>(channels::kQueryAll,
                                                       [&](const MessageRef<query_t>& q) { kept.push_back(q); }));
  }
  robots[0]->Publish(channels::kQueryAll, Query(0, 1));
  robots[0]->Publish(channels::kQueryAll, Query(0, 2));
  sim.Run();
  ASSERT_EQ(kept.size(), 4u);  // robot 1 then robot 2, for each query in turn
  EXPECT_EQ(&*kept[0], &*kept[1]);
  EXPECT_EQ(&*kept[2], &*kept[3]);
  EXPECT_NE(&*kept[0], &*kept[2]);
  EXPECT_EQ(kept[0]->frame, 1);
  EXPECT_EQ(kept[2]->frame, 2);
  EXPECT_EQ(kept[0]->descriptor, std::vector<float>(128, 0.25f));
  kept.clear();  // before `shared`, which they point into
}

TEST_F(SimTransportTest, ClockAndTimersAreVirtual) {
  std::vector<SimTime> fired;
  robots[1]->ScheduleAfter(SimTime::Millis(250), [&] { fired.push_back(robots[1]->Now()); });
  robots[1]->ScheduleAfter(SimTime::Zero(), [&] { fired.push_back(robots[1]->Now()); });
  sim.Run();
  EXPECT_EQ(fired, (std::vector<SimTime>{SimTime::Zero(), SimTime::Millis(250)}));
}

TEST_F(SimTransportTest, DroppedSubscriptionStopsDelivery) {
  int received = 0;
  {
    auto sub = robots[1]->Subscribe<query_t>(channels::kQueryAll, [&](const query_t&) { ++received; });
    robots[0]->Publish(channels::kQueryAll, Query(0, 1));
    sim.Run();
  }
  robots[0]->Publish(channels::kQueryAll, Query(0, 2));
  sim.Run();
  EXPECT_EQ(received, 1);
  EXPECT_EQ(net.Counters(NodeId(0), NodeId(1)).messages, 1u);  // unsubscribed: no longer a destination
}

TEST_F(SimTransportTest, HandlerMayUnsubscribeItselfWithoutSkippingTheNext) {
  std::vector<std::string> calls;
  Subscription first;
  first = robots[1]->Subscribe<query_t>(channels::kQueryAll, [&](const query_t&) {
    calls.push_back("first");
    first.Reset();
  });
  auto second = robots[1]->Subscribe<query_t>(channels::kQueryAll, [&](const query_t&) { calls.push_back("second"); });
  robots[0]->Publish(channels::kQueryAll, Query(0, 1));
  robots[0]->Publish(channels::kQueryAll, Query(0, 2));
  sim.Run();
  EXPECT_EQ(calls, (std::vector<std::string>{"first", "second", "second"}));
}

TEST_F(SimTransportTest, WrongTypeOnAChannelIsCountedAsMalformed) {
  int received = 0;
  auto sub = robots[1]->Subscribe<query_t>(channels::kQueryAll, [&](const query_t&) { ++received; });
  robots[0]->Publish(channels::kQueryAll, match_t{});
  sim.Run();
  EXPECT_EQ(received, 0);
  EXPECT_EQ(robots[1]->MalformedCount(), 1u);
}

}  // namespace
}  // namespace dvpr
