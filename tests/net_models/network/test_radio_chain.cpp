// The radio's hand-worked chain (docs/network_model.md, "The radio"): four robots 150 m apart on
// a line, a 200 m range, 1 Mbit/s radios with 2 ms of processing per hop. Robot 0's message for
// robot 3 takes three hops with shortest_path and is lost out of range with direct routing.
//
// One 505-byte payload on channel "ALL" is one 547-byte frame (docs/network_model.md): 4.376 ms
// on the air at 1 Mbit/s. Each hop: 4.376 ms + 2 ms + 150 m / 299792458 m/s (500.35 ns, 500 ns
// rounded) = 6 376 500 ns; three hops 19 129 500 ns.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "net_models/medium/radio_link.h"
#include "net_models/mobility/fixed_mobility.h"
#include "net_models/network/network.h"
#include "net_models/propagation/range_propagation.h"
#include "net_models/routing/direct_routing.h"
#include "net_models/routing/shortest_path_routing.h"
#include "sim/simulator.h"
#include "tests/net_models/copy_log.h"

namespace dvpr {
namespace {

using Log = testing_support::CopyLog;

enum class Routing { kDirect, kShortestPath };

struct Chain {
  explicit Chain(Routing routing) : net(sim, 4, Stack(routing)) {
    channel = net.InternChannel("ALL");
    type = net.InternType("dvpr.test_t");
    for (int i = 0; i < 4; ++i) net.Join(NodeId(i), channel);
  }
  static NetworkStack Stack(Routing routing) {
    NetworkStack s;
    s.mobility = std::make_unique<FixedMobility>(
        std::vector<Position>{{0, 0, 0}, {150, 0, 0}, {300, 0, 0}, {450, 0, 0}});
    s.propagation = std::make_unique<RangePropagation>(*s.mobility, 200.0);
    s.access = std::make_unique<RadioLink>(RadioLinkParams{DataRate::Mbps(1), SimTime::Millis(2), 100}, 4);
    if (routing == Routing::kShortestPath) {
      s.next_hop = std::make_unique<ShortestPathNextHop>(*s.propagation, 4);
    } else {
      s.next_hop = std::make_unique<DirectNextHop>();
    }
    return s;
  }
  Simulator sim;
  Network net;
  Log log;
  ObserverSubscription subscription = net.Subscribe(log);
  // Robot 0's 505-byte message for robot 3 alone, run to the end.
  void ZeroToThree() {
    const NodeId three[] = {NodeId(3)};
    net.SendTo(NodeId(0), three, channel, type, std::vector<std::uint8_t>(505, 1));
    sim.Run();
  }
  ChannelId channel{};
  MessageTypeId type{};
};

TEST(RadioChain, ShortestPathTakesThreeHopsToTheHandWorkedNanosecond) {
  Chain c(Routing::kShortestPath);
  c.ZeroToThree();
  EXPECT_EQ(c.log.lines, (std::vector<std::string>{"0>3 delivered at 19129500ns"}));
  EXPECT_EQ(c.log.senders, (std::vector<int>{0, 1, 2}));  // robot 0, then the relays 1 and 2
  for (const int r : {0, 1, 2}) {
    EXPECT_EQ(c.net.Sender(NodeId(r)).transmissions, 1u) << r;
    EXPECT_EQ(c.net.Sender(NodeId(r)).medium_bytes, 547) << r;
  }
  EXPECT_EQ(c.net.Sender(NodeId(3)).transmissions, 0u);
  // Robot 0's transmission is its own message; robots 1 and 2 each relayed once, 547 bytes.
  EXPECT_EQ(c.net.Sender(NodeId(0)).relay_transmissions, 0u);
  EXPECT_EQ(c.net.Sender(NodeId(0)).relay_bytes, 0);
  for (const int r : {1, 2}) {
    EXPECT_EQ(c.net.Sender(NodeId(r)).relay_transmissions, 1u) << r;
    EXPECT_EQ(c.net.Sender(NodeId(r)).relay_bytes, 547) << r;
  }
  EXPECT_EQ(c.log.delivered_hops, (std::vector<int>{3}));
  const RouteCounters& routes = c.net.Routes();
  EXPECT_EQ(routes.delivered, 1u);
  EXPECT_EQ(routes.delivered_hops, 3u);
  EXPECT_EQ(routes.max_hops, 3);
  EXPECT_EQ(routes.dropped, (std::array<std::uint64_t, kDropReasons>{}));
}

TEST(RadioChain, DirectRoutingLosesItOutOfRange) {
  Chain c(Routing::kDirect);
  c.ZeroToThree();
  EXPECT_EQ(c.log.lines, (std::vector<std::string>{"0>3 at 0ns: out_of_range"}));
  EXPECT_EQ(c.net.Counters(NodeId(0), NodeId(3)).dropped, 1u);
  std::array<std::uint64_t, kDropReasons> dropped{};
  dropped[static_cast<std::size_t>(DropReason::kOutOfRange)] = 1;
  EXPECT_EQ(c.net.Routes().dropped, dropped);
  EXPECT_EQ(c.net.Routes().delivered, 0u);
}

// A broadcast travels down the shortest-path tree: robot 1 hears robot 0's one transmission, and
// robots 1 and 2 each relay once. Robot 1 gets it after one hop, 2 after two, 3 after three.
TEST(RadioChain, ABroadcastIsOneTransmissionPerRelay) {
  Chain c(Routing::kShortestPath);
  c.net.Send(NodeId(0), c.channel, c.type, std::vector<std::uint8_t>(505, 1));
  c.sim.Run();
  EXPECT_EQ(c.log.lines, (std::vector<std::string>{"0>1 delivered at 6376500ns", "0>2 delivered at 12753000ns",
                                                   "0>3 delivered at 19129500ns"}));
  EXPECT_EQ(c.log.senders, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(c.log.delivered_hops, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(c.net.Routes().delivered_hops, 6u);
  EXPECT_EQ(c.net.Routes().max_hops, 3);
}

// Routing that changes under a copy can pass it back and forth; the copy then stops after
// Network::kMaxHops transmissions instead of circling for ever. Here robots 0 and 1 each name
// the other as the way to robot 3: a loop from the first hop.
class PingPong final : public NextHopRouting {
 private:
  void DoNextHops(NodeId at, std::span<const NodeId>, SimTime, std::span<NodeId> hops) override {
    for (NodeId& h : hops) h = NodeId(at.value == 0 ? 1 : 0);
  }
  std::string_view DoName() const override { return "ping_pong"; }
};

TEST(RadioChain, ALoopingCopyIsDroppedAtTheHopLimit) {
  NetworkStack s = Chain::Stack(Routing::kDirect);
  s.next_hop = std::make_unique<PingPong>();
  Simulator sim;
  Network net(sim, 4, std::move(s));
  Log log;
  const ObserverSubscription subscription = net.Subscribe(log);
  const NodeId three[] = {NodeId(3)};
  net.SendTo(NodeId(0), three, net.InternChannel("ALL"), net.InternType("dvpr.test_t"),
             std::vector<std::uint8_t>(505, 1));
  sim.Run();
  // 64 transmissions of one 150 m hop each (6 376 500 ns, above): robot 0 sends the 1st, 3rd,
  // ..., 63rd, robot 1 the others; the 64th arrives back at robot 0, which drops it. Robot 0's
  // sends are all of its own message, so none counts as relaying.
  ASSERT_EQ(Network::kMaxHops, 64);
  EXPECT_EQ(log.lines, (std::vector<std::string>{"0>3 at 408096000ns: hop_limit"}));
  EXPECT_EQ(log.senders.size(), 64u);
  EXPECT_EQ(net.Sender(NodeId(0)).transmissions, 32u);
  EXPECT_EQ(net.Sender(NodeId(0)).relay_transmissions, 0u);
  EXPECT_EQ(net.Sender(NodeId(1)).relay_transmissions, 32u);
  EXPECT_EQ(net.Routes().dropped[static_cast<std::size_t>(DropReason::kHopLimit)], 1u);
  EXPECT_EQ(net.Counters(NodeId(0), NodeId(3)).dropped, 1u);
}

}  // namespace
}  // namespace dvpr
