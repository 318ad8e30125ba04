// The network's four layers (net_models/network/network_stack.h): the defaults reproduce the link
// model's own answer, and a propagation or routing model plugged into the stack changes what a
// copy does, worked out by hand. The stand-in models below are what a next model looks like:
// one class over the layer's interface, nothing else touched.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "net_models/helper/network_helper.h"
#include "net_models/medium/point_to_point_link.h"
#include "net_models/mobility/fixed_mobility.h"
#include "net_models/network/network.h"
#include "net_models/propagation/full_mesh_propagation.h"
#include "net_models/routing/direct_routing.h"
#include "sim/simulator.h"
#include "tests/net_models/copy_log.h"

namespace dvpr {
namespace {

// Hears within 50 m; the air adds 10 ns per metre.
class DiscPropagation final : public PropagationModel {
 public:
  explicit DiscPropagation(const MobilityModel& mobility) : mobility_(mobility) {}

 private:
  void DoReach(NodeId src, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out) override {
    for (std::size_t i = 0; i < receivers.size(); ++i) {
      const double d = Distance(mobility_.PositionOf(src, now), mobility_.PositionOf(receivers[i], now));
      out[i] = d <= 50.0 ? Reception{true, SimTime::Nanos(std::llround(d * 10))} : Reception{false, SimTime::Zero()};
    }
  }
  std::string_view DoName() const override { return "disc(50m)"; }
  const MobilityModel& mobility_;
};

// Knows no way to one node; answers `hop` for another (a relay, or a bad answer).
class TestRouting final : public NextHopRouting {
 public:
  TestRouting(NodeId unreachable, NodeId relayed = kNoRoute, NodeId hop = kNoRoute)
      : unreachable_(unreachable), relayed_(relayed), hop_(hop) {}

 private:
  void DoNextHops(NodeId, std::span<const NodeId> dsts, SimTime, std::span<NodeId> hops) override {
    for (std::size_t i = 0; i < dsts.size(); ++i) {
      if (dsts[i] == unreachable_) hops[i] = kNoRoute;
      if (dsts[i] == relayed_) hops[i] = hop_;
    }
  }
  std::string_view DoName() const override { return "test"; }
  NodeId unreachable_, relayed_, hop_;
};

using Drops = testing_support::CopyLog;

std::unique_ptr<LinkModel> OneMbps(int nodes) {
  return std::make_unique<PointToPointLink>(PointToPointParams{DataRate::Mbps(1), SimTime::Millis(5), 100, {}}, nodes);
}

// Three nodes on 1 Mbit/s, 5 ms point-to-point links; node 0 broadcasts a 505-byte payload on
// "ALL" (a 547-byte frame, 9.376 ms to arrive: docs/network_model.md).
struct StackRun {
  explicit StackRun(NetworkStack stack) : net(sim, 3, std::move(stack)) {
    all = net.InternChannel("ALL");
    type = net.InternType("dvpr.test_t");
    for (int i = 0; i < 3; ++i) net.Join(NodeId(i), all);
  }
  void Broadcast() {
    net.Send(NodeId(0), all, type, std::vector<std::uint8_t>(505, 1));
    sim.Run();
  }
  Simulator sim;
  Network net;
  Drops drops;
  ObserverSubscription subscription = net.Subscribe(drops);
  ChannelId all{};
  MessageTypeId type{};
};

NetworkStack Stack(std::unique_ptr<MobilityModel> mobility, std::unique_ptr<NextHopRouting> routing) {
  NetworkStack s;
  s.mobility = std::move(mobility);
  s.access = OneMbps(3);
  s.next_hop = std::move(routing);
  return s;
}

TEST(NetworkStack, TheDefaultsAreFixedAtTheOriginTheFullMeshAndDirectRouting) {
  Simulator sim;
  Network net(sim, 3, OneMbps(3));
  EXPECT_EQ(net.mobility().Name(), "fixed");
  EXPECT_EQ(net.mobility().nodes(), 3);
  EXPECT_EQ(net.mobility().PositionOf(NodeId(2), SimTime::Seconds(5)), (Position{0, 0, 0}));
  EXPECT_EQ(net.propagation().Name(), "full_mesh");
  EXPECT_EQ(net.next_hop().Name(), "direct");
  EXPECT_EQ(net.link().Name(), "point_to_point");
}

TEST(NetworkStack, MakeNetworkStackGivesTheConfiguredLinkAsTheMediumAccess) {
  NetworkModelParams params;
  params.model = LinkModelKind::kSharedMedium;
  NetworkStack stack = MakeNetworkStack(params, 4, 1, std::make_unique<FixedMobility>(FixedMobility::AtOrigin(4)));
  EXPECT_EQ(stack.access->Name(), "shared_medium");
  EXPECT_EQ(stack.propagation->Name(), "full_mesh");
  EXPECT_EQ(stack.next_hop->Name(), "direct");
  EXPECT_EQ(stack.mobility->nodes(), 4);
}

TEST(NetworkStack, AMobilityModelForAnotherTeamSizeIsRefused) {
  Simulator sim;
  NetworkStack stack;
  stack.access = OneMbps(3);
  stack.mobility = std::make_unique<FixedMobility>(FixedMobility::AtOrigin(2));
  try {
    Network net(sim, 3, std::move(stack));
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "NetworkStack: the mobility model places 2 nodes, the network has 3");
  }
  EXPECT_THROW(Network(sim, 3, NetworkStack{}), std::invalid_argument);  // no medium access
}

TEST(NetworkStack, FullMeshAndDirectRoutingDeliverAsTheLinkAlone) {
  StackRun run(Stack(nullptr, std::make_unique<DirectNextHop>()));
  run.Broadcast();
  EXPECT_EQ(run.drops.lines, (std::vector<std::string>{"0>1 delivered at 9376000ns", "0>2 delivered at 9376000ns"}));
  EXPECT_EQ(run.net.Sender(NodeId(0)).transmissions, 2u);
  EXPECT_EQ(run.net.Sender(NodeId(0)).medium_bytes, 2 * 547);
}

TEST(NetworkStack, ACopyOutOfRangeIsDroppedAndOneInRangeArrivesThePropagationDelayLater) {
  // Node 1 is 50 m away (30, 40): heard, 500 ns of air; node 2 is 60 m away: not heard.
  NetworkStack stack;
  stack.mobility = std::make_unique<FixedMobility>(std::vector<Position>{{0, 0, 0}, {30, 40, 0}, {0, 0, 60}});
  stack.propagation = std::make_unique<DiscPropagation>(*stack.mobility);
  stack.access = OneMbps(3);
  StackRun run(std::move(stack));
  EXPECT_EQ(run.net.propagation().Name(), "disc(50m)");
  run.Broadcast();
  EXPECT_EQ(run.drops.lines, (std::vector<std::string>{"0>2 at 0ns: out_of_range", "0>1 delivered at 9376500ns"}));
  // Both copies went on the air; the one nobody heard counts as dropped on its pair.
  EXPECT_EQ(run.net.Sender(NodeId(0)).transmissions, 2u);
  EXPECT_EQ(run.net.Sender(NodeId(0)).medium_bytes, 2 * 547);
  EXPECT_EQ(run.net.Counters(NodeId(0), NodeId(2)).dropped, 1u);
  EXPECT_EQ(run.net.Counters(NodeId(0), NodeId(1)).delivered, 1u);
}

TEST(NetworkStack, ACopyWithoutARouteNeverGoesOnTheMedium) {
  StackRun run(Stack(nullptr, std::make_unique<TestRouting>(NodeId(1))));
  run.Broadcast();
  EXPECT_EQ(run.drops.lines, (std::vector<std::string>{"0>1 at 0ns: no_route", "0>2 delivered at 9376000ns"}));
  EXPECT_EQ(run.net.Sender(NodeId(0)).transmissions, 1u);
  EXPECT_EQ(run.net.Sender(NodeId(0)).medium_bytes, 547);
  EXPECT_EQ(run.net.Counters(NodeId(0), NodeId(1)).dropped, 1u);
  EXPECT_EQ(run.net.Counters(NodeId(0), NodeId(1)).messages, 1u);
}

TEST(NetworkStack, NoRouteToAnyDestinationPutsNothingOnTheMedium) {
  StackRun run(Stack(nullptr, std::make_unique<TestRouting>(NodeId(1), NodeId(2), kNoRoute)));
  run.Broadcast();
  EXPECT_EQ(run.drops.lines, (std::vector<std::string>{"0>1 at 0ns: no_route", "0>2 at 0ns: no_route"}));
  EXPECT_EQ(run.net.Sender(NodeId(0)).transmissions, 0u);
  EXPECT_EQ(run.net.Sender(NodeId(0)).medium_bytes, 0);
}

// From node 0 the way to node 2 is through node 1; every other hop is direct.
class ThroughOne final : public NextHopRouting {
 private:
  void DoNextHops(NodeId at, std::span<const NodeId> dsts, SimTime, std::span<NodeId> hops) override {
    for (std::size_t i = 0; i < dsts.size(); ++i) {
      if (at == NodeId(0) && dsts[i] == NodeId(2)) hops[i] = NodeId(1);
    }
  }
  std::string_view DoName() const override { return "through_one"; }
};

TEST(NetworkStack, ARelayedCopyIsTheRelaysOwnTransmission) {
  // 0's broadcast has one next hop, node 1, for both copies: one copy on link 0->1, arriving at
  // 9.376 ms; node 1 takes its own and sends node 2's on, over link 1->2: 9.376 ms later.
  StackRun run(Stack(nullptr, std::make_unique<ThroughOne>()));
  run.Broadcast();
  EXPECT_EQ(run.drops.lines,
            (std::vector<std::string>{"0>1 delivered at 9376000ns", "0>2 delivered at 18752000ns"}));
  EXPECT_EQ(run.net.Sender(NodeId(0)).transmissions, 1u);
  EXPECT_EQ(run.net.Sender(NodeId(0)).medium_bytes, 547);
  EXPECT_EQ(run.net.Sender(NodeId(1)).transmissions, 1u);  // the relay's bytes are its own
  EXPECT_EQ(run.net.Sender(NodeId(1)).medium_bytes, 547);
  EXPECT_EQ(run.net.Sender(NodeId(1)).published, 0u);
  // The pair counts the message end to end: once, delivered.
  EXPECT_EQ(run.net.Counters(NodeId(0), NodeId(2)).messages, 1u);
  EXPECT_EQ(run.net.Counters(NodeId(0), NodeId(2)).delivered, 1u);
  EXPECT_EQ(run.net.Counters(NodeId(1), NodeId(2)).messages, 0u);
}

TEST(NetworkStack, AnOfflineRelayDropsWhatItWouldSendOn) {
  StackRun run(Stack(nullptr, std::make_unique<ThroughOne>()));
  run.net.SetOffline(NodeId(1), SimTime::Millis(1));
  run.Broadcast();
  // Node 1's own copy arrives while it is offline (dropped at delivery); the relayed one is
  // dropped when node 1 would send it on.
  EXPECT_EQ(run.drops.lines,
            (std::vector<std::string>{"0>1 at 9376000ns: offline", "0>2 at 9376000ns: offline"}));
  EXPECT_EQ(run.net.Sender(NodeId(1)).transmissions, 0u);
  EXPECT_EQ(run.net.Counters(NodeId(0), NodeId(2)).dropped, 1u);
}

TEST(NetworkStack, ANextHopThatIsNoNeighbourIsAnError) {
  for (const NodeId bad : {NodeId(0), NodeId(3), NodeId(-2)}) {
    StackRun run(Stack(nullptr, std::make_unique<TestRouting>(kNoRoute, NodeId(2), bad)));
    try {
      run.Broadcast();
      FAIL() << "accepted hop " << bad.value;
    } catch (const std::logic_error& e) {
      EXPECT_EQ(std::string(e.what()), "NextHopRouting 'test': next hop " + std::to_string(bad.value) +
                                           " from node 0 to 2 is not a neighbour in [0, 3)");
    }
  }
}

TEST(NetworkStack, AnOfflineSenderAsksNoLayer) {
  // The routing would refuse every hop; an offline sender never gets that far.
  StackRun run(Stack(nullptr, std::make_unique<TestRouting>(kNoRoute, NodeId(2), NodeId(0))));
  run.net.SetOffline(NodeId(0), SimTime::Zero());
  run.net.Send(NodeId(0), run.all, run.type, std::vector<std::uint8_t>(505, 1));
  EXPECT_EQ(run.drops.lines, (std::vector<std::string>{"0>1 at 0ns: offline", "0>2 at 0ns: offline"}));
}

}  // namespace
}  // namespace dvpr
