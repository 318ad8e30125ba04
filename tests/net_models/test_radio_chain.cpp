// The radio's hand-worked chain (docs/network_model.md, "The radio"): four robots 150 m apart on
// a line, a 200 m range, 1 Mbit/s radios with 2 ms of processing per hop. Robot 0's message for
// robot 3 takes three hops with shortest_path and is lost out of range with direct routing.
//
// One 505-byte payload on channel "ALL" is one 547-byte frame (docs/network_model.md): 4.376 ms
// on the air at 1 Mbit/s. Each hop: 4.376 ms + 2 ms + 150 m / 299792458 m/s (500.35 ns, 500 ns
// rounded) = 6 376 500 ns; three hops 19 129 500 ns.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "net_models/direct_routing.h"
#include "net_models/fixed_mobility.h"
#include "net_models/network.h"
#include "net_models/radio_link.h"
#include "net_models/range_propagation.h"
#include "net_models/shortest_path_routing.h"
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
      s.routing = std::make_unique<ShortestPathRouting>(*s.propagation, 4);
    } else {
      s.routing = std::make_unique<DirectRouting>();
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
}

TEST(RadioChain, DirectRoutingLosesItOutOfRange) {
  Chain c(Routing::kDirect);
  c.ZeroToThree();
  EXPECT_EQ(c.log.lines, (std::vector<std::string>{"0>3 at 0ns: out_of_range"}));
  EXPECT_EQ(c.net.Counters(NodeId(0), NodeId(3)).dropped, 1u);
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
}

}  // namespace
}  // namespace dvpr
