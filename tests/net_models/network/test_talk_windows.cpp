// Talk windows (Network::SetTalkWindows, issue 35's connectivity schedule): outside its windows a
// robot sends and receives nothing. Two robots 150 m apart on 1 Mbit/s radios of 200 m range with
// 2 ms of processing per hop: one hop of a 505-byte payload (a 547-byte frame) takes
// 547 x 8 us + 2 ms + 150 m / c = 6 376 500 ns (tests/net_models/network/test_radio_chain.cpp works it).
// Robot 1 talks only in [1 s, 2 s).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "net_models/medium/radio_link.h"
#include "net_models/mobility/fixed_mobility.h"
#include "net_models/network/network.h"
#include "net_models/propagation/range_propagation.h"
#include "net_models/routing/shortest_path_routing.h"
#include "sim/simulator.h"
#include "tests/net_models/copy_log.h"

namespace dvpr {
namespace {

constexpr std::int64_t kHopNs = 6'376'500;

struct Pair {
  explicit Pair(DisconnectedParams disconnected = {}) : net(sim, 2, Stack(disconnected)) {
    channel = net.InternChannel("ALL");
    type = net.InternType("dvpr.test_t");
    net.SetTalkWindows(NodeId(1), {TalkWindow{SimTime::Seconds(1), SimTime::Seconds(2)}});
  }
  static NetworkStack Stack(DisconnectedParams disconnected) {
    NetworkStack s;
    s.mobility = std::make_unique<FixedMobility>(std::vector<Position>{{0, 0, 0}, {150, 0, 0}});
    s.propagation = std::make_unique<RangePropagation>(*s.mobility, 200.0);
    s.access = std::make_unique<RadioLink>(RadioLinkParams{DataRate::Mbps(1), SimTime::Millis(2), 100}, 2);
    s.next_hop = std::make_unique<ShortestPathNextHop>(*s.propagation, 2);
    s.disconnected = disconnected;
    return s;
  }
  // `from` sends a 505-byte message to the other robot at `at`.
  void SendAt(SimTime at, int from) {
    sim.ScheduleAt(at, [this, from] {
      const NodeId to[] = {NodeId(1 - from)};
      net.SendTo(NodeId(from), to, channel, type, std::vector<std::uint8_t>(505, 1));
    });
  }
  Simulator sim;
  Network net;
  testing_support::CopyLog log;
  ObserverSubscription subscription = net.Subscribe(log);
  ChannelId channel{};
  MessageTypeId type{};
};

std::string Delivered(const char* pair, std::int64_t ns) { return std::string(pair) + " delivered at " + std::to_string(ns) + "ns"; }

TEST(TalkWindows, OnlineFromTheWindowsOpeningUntilJustBeforeItCloses) {
  Simulator sim;
  Network net(sim, 2, Pair::Stack({}));
  net.SetTalkWindows(NodeId(0), {TalkWindow{SimTime::Seconds(1), SimTime::Seconds(2)},
                                 TalkWindow{SimTime::Seconds(5), SimTime::Seconds(6)}});
  const std::vector<std::pair<std::int64_t, bool>> expected = {
      {0, false}, {999'999'999, false}, {1'000'000'000, true}, {1'999'999'999, true}, {2'000'000'000, false},
      {4'999'999'999, false}, {5'000'000'000, true}, {6'000'000'000, false}, {100'000'000'000, false}};
  for (const auto& [ns, online] : expected) {
    EXPECT_EQ(net.IsOnline(NodeId(0), SimTime::Nanos(ns)), online) << ns;
    EXPECT_TRUE(net.IsOnline(NodeId(1), SimTime::Nanos(ns))) << "robot 1 has no windows: always talks";
  }
}

TEST(TalkWindows, OutsideItsWindowARobotNeitherSendsNorReceives) {
  Pair t;
  t.SendAt(SimTime::Millis(500), 0);   // arrives at 0.506 s, before robot 1's window: lost
  t.SendAt(SimTime::Millis(500), 1);   // robot 1 cannot send yet: lost at once, nothing on the air
  t.SendAt(SimTime::Millis(1500), 0);  // inside the window both ways
  t.SendAt(SimTime::Millis(1500), 1);
  t.SendAt(SimTime::Millis(1995), 0);  // sent inside, arrives at 2.0014 s: the window has closed
  t.sim.Run();
  EXPECT_EQ(t.log.lines, (std::vector<std::string>{
                             "1>0 at 500000000ns: offline",
                             "0>1 at " + std::to_string(500'000'000 + kHopNs) + "ns: offline",
                             Delivered("0>1", 1'500'000'000 + kHopNs),
                             Delivered("1>0", 1'500'000'000 + kHopNs),
                             "0>1 at " + std::to_string(1'995'000'000 + kHopNs) + "ns: offline"}));
  EXPECT_EQ(t.net.Routes().dropped[static_cast<std::size_t>(DropReason::kOffline)], 3u);
  // Robot 1 put one frame on the air (at 1.5 s), robot 0 three.
  EXPECT_EQ(t.net.Sender(NodeId(1)).medium_bytes, 547);
  EXPECT_EQ(t.net.Sender(NodeId(0)).medium_bytes, 3 * 547);
}

DisconnectedParams StoreAndForward(SimTime hold_time = SimTime::Seconds(60)) {
  return DisconnectedParams{.kind = DisconnectedKind::kStoreAndForward, .hold_bytes = Bytes(10'000'000),
                            .hold_time = hold_time};
}

TEST(TalkWindows, WithStoreAndForwardASenderKeepsItsMessageForItsNextWindow) {
  // Held at 0.5 s; the retries at 0.6 .. 0.9 s fall outside the window, the one at 1.0 s inside.
  Pair t(StoreAndForward());
  t.SendAt(SimTime::Millis(500), 1);
  t.sim.Run();
  EXPECT_EQ(t.log.lines, (std::vector<std::string>{Delivered("1>0", 1'000'000'000 + kHopNs)}));
  EXPECT_EQ(t.net.Routes().held, 1u);
}

TEST(TalkWindows, WithStoreAndForwardWhatArrivesOutsideTheWindowIsStillLost) {
  // The sender cannot know the receiver is not listening: its copy goes on the air and is lost.
  Pair t(StoreAndForward());
  t.SendAt(SimTime::Millis(500), 0);
  t.sim.Run();
  EXPECT_EQ(t.log.lines, (std::vector<std::string>{"0>1 at " + std::to_string(500'000'000 + kHopNs) + "ns: offline"}));
  EXPECT_EQ(t.net.Routes().held, 0u);
}

TEST(TalkWindows, AHeldMessageExpiresWhenNoWindowComesInTime) {
  // Sent at 2.5 s, after robot 1's only window; held 0.5 s, it expires at the 3.0 s retry.
  Pair t(StoreAndForward(SimTime::Millis(500)));
  t.SendAt(SimTime::Millis(2500), 1);
  t.sim.Run();
  EXPECT_EQ(t.log.lines, (std::vector<std::string>{"1>0 at 3000000000ns: expired"}));
  EXPECT_EQ(t.net.Sender(NodeId(1)).medium_bytes, 0);
}

TEST(TalkWindows, WindowsMustBeNonEmptyAscendingAndDisjoint) {
  Simulator sim;
  Network net(sim, 2, Pair::Stack({}));
  const SimTime s1 = SimTime::Seconds(1), s2 = SimTime::Seconds(2), s3 = SimTime::Seconds(3);
  EXPECT_THROW(net.SetTalkWindows(NodeId(0), {TalkWindow{s2, s1}}), std::invalid_argument);
  EXPECT_THROW(net.SetTalkWindows(NodeId(0), {TalkWindow{s1, s1}}), std::invalid_argument);
  EXPECT_THROW(net.SetTalkWindows(NodeId(0), {TalkWindow{s1, s3}, TalkWindow{s2, SimTime::Seconds(4)}}),
               std::invalid_argument);
  EXPECT_THROW(net.SetTalkWindows(NodeId(2), {}), std::out_of_range);
  net.SetTalkWindows(NodeId(0), {TalkWindow{s1, s2}, TalkWindow{s2, s3}});  // touching is fine
  EXPECT_TRUE(net.IsOnline(NodeId(0), s2));
}

}  // namespace
}  // namespace dvpr
