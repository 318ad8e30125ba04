#include "net_models/network.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "net_models/ideal_link.h"
#include "net_models/message_csv.h"
#include "net_models/point_to_point_link.h"
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
    net.EnableRecords(true);
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
  small.EnableRecords(true);
  const NodeId to1[] = {NodeId(1)};
  for (int i = 0; i < 4; ++i) small.SendTo(NodeId(0), to1, c, type, Payload(505));
  sim.Run();
  const LinkCounters& k = small.Counters(NodeId(0), NodeId(1));
  EXPECT_EQ(k.messages, 4u);
  EXPECT_EQ(k.delivered, 2u);  // one on the wire, one waiting
  EXPECT_EQ(k.dropped, 2u);
  EXPECT_EQ(small.Records()[3].drop, DropReason::kQueueFull);
}

TEST_F(NetworkTest, OfflineRobotLosesWhatArrivesAndWhatItSends) {
  net.SetOffline(NodeId(2), SimTime::Millis(1));  // before the 9.376 ms arrival
  net.Send(NodeId(0), all, type, Payload(505));
  sim.Run();
  EXPECT_EQ(arrivals.size(), 2u);
  EXPECT_EQ(net.Counters(NodeId(0), NodeId(2)).dropped, 1u);
  EXPECT_EQ(net.Records()[1].drop, DropReason::kOffline);
  net.Send(NodeId(2), all, type, Payload(505));  // the offline robot sends: nothing leaves
  sim.Run();
  EXPECT_EQ(arrivals.size(), 2u);
  EXPECT_EQ(net.Counters(NodeId(2), NodeId(0)).dropped, 1u);
  EXPECT_EQ(net.Sender(NodeId(2)).transmissions, 0u);
}

TEST_F(NetworkTest, LeaveStopsDelivery) {
  net.Leave(NodeId(3), all);
  EXPECT_EQ(net.Send(NodeId(0), all, type, Payload(10)), 2u);
}

TEST_F(NetworkTest, MessagesCsvHasOneRowPerMessageAndDestination) {
  net.SetOffline(NodeId(3), SimTime::Zero());
  net.Send(NodeId(0), all, type, Payload(505));
  sim.Run();
  std::ostringstream csv;
  WriteMessagesCsvHeader(csv);
  AppendMessagesCsv(csv, net, RunLabels{"sim", "broadcast", "4", "0"});
  EXPECT_EQ(csv.str(),
            "protocol,strategy,robots,run,sent_ns,delivered_ns,src,dst,channel,type,payload_bytes,wire_bytes,dropped\n"
            "sim,broadcast,4,0,0,9376000,0,1,ALL,dvpr.test_t,505,547,0\n"
            "sim,broadcast,4,0,0,9376000,0,2,ALL,dvpr.test_t,505,547,0\n"
            "sim,broadcast,4,0,0,,0,3,ALL,dvpr.test_t,505,547,1\n");
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
