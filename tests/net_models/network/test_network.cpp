#include "net_models/network/network.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "net_models/medium/ideal_link.h"
#include "net_models/medium/point_to_point_link.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

struct Arrival {
  SimTime at;
  NodeId src;
  NodeId dst;
  std::string channel;
  std::vector<std::uint8_t> payload;
};

class Recorder : public NetworkEndpoint {
 public:
  Recorder(Simulator& sim, std::vector<Arrival>& log) : sim_(sim), log_(log) {}
  void OnReceive(const ReceivedMessage& m) override {
    log_.push_back({sim_.Now(), m.src, m.dst, std::string(m.channel_name), {m.payload.begin(), m.payload.end()}});
  }

 private:
  Simulator& sim_;
  std::vector<Arrival>& log_;
};

// What the hooks reported, one line per call: "sent 0>2 #3 msg 1 at 0ns",
// "delivered 0>2 #3 at 9376000ns", "dropped 0>3 #4 at 0ns: offline".
class HookLog : public NetworkObserver {
 public:
  void OnSent(const MessageCopy& c) override {
    lines.push_back("sent " + Copy(c) + " msg " + std::to_string(c.message) + " at " + std::to_string(c.sent.ns()) +
                    "ns " + std::string(c.channel_name) + " " + std::string(c.type_name) + " " +
                    std::to_string(c.payload.size()) + "B wire " + std::to_string(c.wire_bytes) + "B");
  }
  void OnDelivered(const MessageCopy& c, SimTime at) override {
    lines.push_back("delivered " + Copy(c) + " at " + std::to_string(at.ns()) + "ns");
  }
  void OnDropped(const MessageCopy& c, SimTime at, DropReason reason) override {
    lines.push_back("dropped " + Copy(c) + " at " + std::to_string(at.ns()) + "ns: " + std::string(ToString(reason)));
  }
  std::vector<std::string> lines;

 private:
  static std::string Copy(const MessageCopy& c) {
    return std::to_string(c.src.value) + ">" + std::to_string(c.dst.value) + " #" + std::to_string(c.copy);
  }
};

// Four nodes on 1 Mbit/s, 5 ms point-to-point links; everyone joins "ALL",
// only node 2 joins "Q_2". Channel "ALL" is 3 characters long, so a payload of
// 517 - (8 + 3 + 1) = 505 bytes makes a 517-byte UDP payload: a 547-byte frame.
class NetworkTest : public ::testing::Test {
 protected:
  static constexpr int kNodes = 4;
  Simulator sim;
  Network net{sim, kNodes, std::make_unique<PointToPointLink>(
                               PointToPointParams{DataRate::Mbps(1), SimTime::Millis(5), 100, {}}, kNodes)};
  std::vector<Arrival> arrivals;
  std::vector<Recorder> recorders;
  HookLog hooks;
  ObserverSubscription hooks_subscription = net.Subscribe(hooks);
  ChannelId all = net.InternChannel("ALL");
  ChannelId q2 = net.InternChannel("Q_2");
  MessageTypeId type = net.InternType("dvpr.test_t");

  void SetUp() override {
    recorders.reserve(kNodes);
    for (int i = 0; i < kNodes; ++i) {
      recorders.emplace_back(sim, arrivals);
      net.Attach(NodeId(i), &recorders.back());
      net.Join(NodeId(i), all);
    }
    net.Join(NodeId(2), q2);
  }
  static std::vector<std::uint8_t> Payload(std::size_t n, std::uint8_t fill = 7) {
    return std::vector<std::uint8_t>(n, fill);
  }
};

TEST_F(NetworkTest, FrameOf547BytesArrivesAfter9376Microseconds) {
  EXPECT_EQ(net.Send(NodeId(0), q2, type, Payload(505)), 1u);
  sim.Run();
  ASSERT_EQ(arrivals.size(), 1u);
  EXPECT_EQ(arrivals[0].at, SimTime::Micros(9376));
  EXPECT_EQ(arrivals[0].dst, NodeId(2));
  EXPECT_EQ(net.Counters(NodeId(0), NodeId(2)).wire_bytes, 547);
}

TEST_F(NetworkTest, BroadcastGoesToEverySubscriberButTheSender) {
  EXPECT_EQ(net.Send(NodeId(1), all, type, Payload(505, 42)), 3u);
  sim.Run();
  ASSERT_EQ(arrivals.size(), 3u);
  std::vector<int> dsts;
  for (const auto& a : arrivals) {
    dsts.push_back(a.dst.value);
    EXPECT_EQ(a.src, NodeId(1));
    EXPECT_EQ(a.channel, "ALL");
    EXPECT_EQ(a.payload, Payload(505, 42));
    EXPECT_EQ(a.at, SimTime::Micros(9376));
  }
  EXPECT_EQ(dsts, (std::vector<int>{0, 2, 3}));  // same arrival time: FIFO in send order
  EXPECT_EQ(net.Sender(NodeId(1)).transmissions, 3u);
  EXPECT_EQ(net.Sender(NodeId(1)).medium_bytes, 3 * 547);
}

TEST_F(NetworkTest, CountsPerDirectedPair) {
  net.Send(NodeId(0), q2, type, Payload(505));
  net.Send(NodeId(0), q2, type, Payload(1000));  // UDP 1012 -> IP 1040 -> frame 1042
  net.Send(NodeId(3), all, type, Payload(505));
  sim.Run();
  const LinkCounters& c02 = net.Counters(NodeId(0), NodeId(2));
  EXPECT_EQ(c02.messages, 2u);
  EXPECT_EQ(c02.payload_bytes, 1505);
  EXPECT_EQ(c02.wire_bytes, 547 + 1042);
  EXPECT_EQ(c02.delivered, 2u);
  EXPECT_EQ(net.Counters(NodeId(2), NodeId(0)).messages, 0u);
  EXPECT_EQ(net.Counters(NodeId(3), NodeId(1)).messages, 1u);
  const LinkCounters t = net.Totals();
  EXPECT_EQ(t.messages, 5u);
  EXPECT_EQ(t.wire_bytes, 547 + 1042 + 3 * 547);
}

TEST_F(NetworkTest, FullQueueDropsAreCounted) {
  Network small(sim, 2, std::make_unique<PointToPointLink>(
                            PointToPointParams{DataRate::Mbps(1), SimTime::Millis(5), 1, {}}, 2));
  const ChannelId c = small.InternChannel("ALL");
  const MessageTypeId t = small.InternType("dvpr.test_t");
  HookLog small_hooks;
  const ObserverSubscription subscription = small.Subscribe(small_hooks);
  const NodeId to1[] = {NodeId(1)};
  for (int i = 0; i < 4; ++i) small.SendTo(NodeId(0), to1, c, t, Payload(505));
  sim.Run();
  const LinkCounters& k = small.Counters(NodeId(0), NodeId(1));
  EXPECT_EQ(k.messages, 4u);
  EXPECT_EQ(k.delivered, 2u);  // one on the wire, one waiting
  EXPECT_EQ(k.dropped, 2u);
  ASSERT_EQ(small_hooks.lines.size(), 8u);  // 4 sent, 2 dropped at once, 2 delivered
  EXPECT_EQ(small_hooks.lines[3], "dropped 0>1 #2 at 0ns: queue_full");
  EXPECT_EQ(small_hooks.lines[5], "dropped 0>1 #3 at 0ns: queue_full");
}

TEST_F(NetworkTest, OfflineRobotLosesWhatArrivesAndWhatItSends) {
  net.SetOffline(NodeId(2), SimTime::Millis(1));  // before the 9.376 ms arrival
  net.Send(NodeId(0), all, type, Payload(505));
  sim.Run();
  EXPECT_EQ(arrivals.size(), 2u);
  EXPECT_EQ(net.Counters(NodeId(0), NodeId(2)).dropped, 1u);
  EXPECT_EQ(std::count(hooks.lines.begin(), hooks.lines.end(), "dropped 0>2 #1 at 9376000ns: offline"), 1);
  net.Send(NodeId(2), all, type, Payload(505));  // the offline robot sends: nothing leaves
  sim.Run();
  EXPECT_EQ(arrivals.size(), 2u);
  EXPECT_EQ(net.Counters(NodeId(2), NodeId(0)).dropped, 1u);
  EXPECT_EQ(net.Sender(NodeId(2)).transmissions, 0u);
}

// The fixture's network interned 2 channels and 1 type; ids past those name nothing.
TEST_F(NetworkTest, IdsNotInternedByThisNetworkAreRejected) {
  const NodeId to1[] = {NodeId(1)};
  EXPECT_THROW(net.SendTo(NodeId(0), to1, ChannelId{2}, type, Payload(1)), std::out_of_range);
  EXPECT_THROW(net.SendTo(NodeId(0), to1, all, MessageTypeId{1}, Payload(1)), std::out_of_range);
  EXPECT_THROW(net.Send(NodeId(0), all, MessageTypeId{1}, Payload(1)), std::out_of_range);
  EXPECT_EQ(net.Sender(NodeId(0)).published, 0u);  // nothing was sent
}

TEST_F(NetworkTest, LeaveStopsDelivery) {
  net.Leave(NodeId(3), all);
  EXPECT_EQ(net.Send(NodeId(0), all, type, Payload(10)), 2u);
}

// One copy per destination; the 547-byte frames arrive after 9.376 ms, where
// node 3 is offline: its copy is dropped then.
TEST_F(NetworkTest, HooksReportEveryCopySentThenDeliveredOrDropped) {
  net.SetOffline(NodeId(3), SimTime::Zero());
  net.Send(NodeId(0), all, type, Payload(505));
  sim.Run();
  EXPECT_EQ(hooks.lines, (std::vector<std::string>{
                             "sent 0>1 #0 msg 0 at 0ns ALL dvpr.test_t 505B wire 547B",
                             "sent 0>2 #1 msg 0 at 0ns ALL dvpr.test_t 505B wire 547B",
                             "sent 0>3 #2 msg 0 at 0ns ALL dvpr.test_t 505B wire 547B",
                             "delivered 0>1 #0 at 9376000ns",
                             "delivered 0>2 #1 at 9376000ns",
                             "dropped 0>3 #2 at 9376000ns: offline",
                         }));
}

// An offline sender's copies are dropped at once, right after their send;
// message and copy numbers run on across sends. A 10-byte payload on "Q_2" is
// an 8 + 3 + 1 + 10 = 22-byte LCM datagram, + 28 = 50-byte IP packet, a
// 52-byte frame.
TEST_F(NetworkTest, HooksNumberMessagesAndCopiesAcrossSends) {
  net.SetOffline(NodeId(1), SimTime::Zero());
  net.Send(NodeId(0), q2, type, Payload(505));
  net.Send(NodeId(1), q2, type, Payload(10));
  sim.Run();
  EXPECT_EQ(hooks.lines, (std::vector<std::string>{
                             "sent 0>2 #0 msg 0 at 0ns Q_2 dvpr.test_t 505B wire 547B",
                             "sent 1>2 #1 msg 1 at 0ns Q_2 dvpr.test_t 10B wire 52B",
                             "dropped 1>2 #1 at 0ns: offline",
                             "delivered 0>2 #0 at 9376000ns",
                         }));
}

TEST_F(NetworkTest, EndedSubscriptionHearsNothingMore) {
  HookLog late;
  {
    const ObserverSubscription subscription = net.Subscribe(late);
    net.Send(NodeId(0), q2, type, Payload(505));
  }
  sim.Run();  // the delivery happens after the subscription ended
  EXPECT_EQ(late.lines.size(), 1u);
  EXPECT_EQ(hooks.lines.size(), 2u);
}

// A broadcast whose copy to node 2 waits behind a unicast on the 1 -> 2 link: its copies arrive
// at two times, and at each time the copies of all messages arrive in the order they were sent
// (message by message, destination by destination). Frames of 547 bytes take 4376 us on 1 Mbit/s.
TEST_F(NetworkTest, CopiesArriveAtTheirOwnTimesInSendOrder) {
  net.Send(NodeId(1), q2, type, Payload(505, 1));   // 1 -> 2: on the link 0 .. 4376 us
  net.Send(NodeId(1), all, type, Payload(505, 2));  // 1 -> 0, 1 -> 3 at once; 1 -> 2 after the first
  net.Send(NodeId(0), all, type, Payload(505, 3));  // 0 -> 1, 2, 3: links idle
  sim.Run();
  std::vector<std::string> got;
  for (const auto& a : arrivals) {
    got.push_back(std::to_string(a.at.us()) + " " + std::to_string(a.src.value) + ">" + std::to_string(a.dst.value) +
                  " #" + std::to_string(a.payload.at(0)));
  }
  EXPECT_EQ(got, (std::vector<std::string>{"9376 1>2 #1", "9376 1>0 #2", "9376 1>3 #2", "9376 0>1 #3", "9376 0>2 #3",
                                           "9376 0>3 #3", "13752 1>2 #2"}));
  EXPECT_EQ(net.Totals().delivered, 7u);
}

TEST(NetworkIdeal, DeliversAtTheSendTimeInSendOrder) {
  Simulator sim;
  Network net(sim, 2, std::make_unique<IdealLink>());
  std::vector<Arrival> log;
  Recorder r(sim, log);
  net.Attach(NodeId(1), &r);
  const ChannelId c = net.InternChannel("C");
  net.Join(NodeId(1), c);
  sim.Schedule(SimTime::Millis(3), [&] {
    net.Send(NodeId(0), c, net.InternType("t"), std::vector<std::uint8_t>{1});
    net.Send(NodeId(0), c, net.InternType("t"), std::vector<std::uint8_t>{2});
  });
  sim.Run();
  ASSERT_EQ(log.size(), 2u);
  EXPECT_EQ(log[0].at, SimTime::Millis(3));
  EXPECT_EQ(log[0].payload, std::vector<std::uint8_t>{1});
  EXPECT_EQ(log[1].payload, std::vector<std::uint8_t>{2});
}

}  // namespace
}  // namespace dvpr
