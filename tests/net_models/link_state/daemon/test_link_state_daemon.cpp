// link_state routing end to end: each robot's daemon (net_models/link_state/daemon/link_state_daemon.h,
// installed by LinkStateHelper) sends its beacons through a SimTransport over a 1 Mbit/s radio with 2 ms of processing per hop and a
// 200 m range; the routing tables they fill route the robots' messages.
//
// Beacon sizes, by hand (lcmtypes/dvpr/routing_*.lcm; wire framing as docs/network_model.md):
//   HELLO with k links: LCM payload 8 (fingerprint) + 2 (robot) + 2 (num_links) + 2k = 12 + 2k;
//     + 8 (LCM header) + 11 ("DVPR_HELLO" and NUL) + 28 (UDP, IPv4) + 2 (framing) = 61 + 2k bytes.
//   TC with k links: 8 + 2 (origin) + 4 (sequence) + 2 + 2k = 16 + 2k;
//     + 8 + 14 ("DVPR_TOPOLOGY" and NUL) + 28 + 2 = 68 + 2k bytes.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "agents/messages/sim_transport.h"
#include "net_models/link_state/daemon/link_state_helper.h"
#include "net_models/medium/radio_link.h"
#include "net_models/mobility/fixed_mobility.h"
#include "net_models/mobility/track_mobility.h"
#include "net_models/network/network.h"
#include "net_models/propagation/range_propagation.h"
#include "sim/simulator.h"

namespace dvpr {
namespace {

SimTime S(double s) { return SimTime::Nanos(std::llround(s * 1e9)); }

// What the test watches: beacon bytes each robot put on the air in a window, and the fate of the
// copies on channel "ALL".
class Watch : public NetworkObserver {
 public:
  void OnMedium(const MediumReport& m) override {
    if (m.sent < from || m.sent >= until) return;
    if (m.channel_name == "DVPR_HELLO") hello_bytes[static_cast<std::size_t>(m.src.value)] += m.bytes;
    if (m.channel_name == "DVPR_TOPOLOGY") topology_bytes[static_cast<std::size_t>(m.src.value)] += m.bytes;
  }
  void OnDelivered(const MessageCopy& c, SimTime at) override {
    if (c.channel_name == "ALL") lines.push_back("delivered at " + std::to_string(at.ns()) + "ns, " + std::to_string(c.hops) + " hops");
  }
  void OnDropped(const MessageCopy& c, SimTime at, DropReason reason) override {
    if (c.channel_name == "ALL") lines.push_back("dropped at " + std::to_string(at.ns()) + "ns: " + std::string(ToString(reason)));
    if (c.channel_name != "ALL") ++beacon_drops;
  }
  SimTime from, until = SimTime::Max();
  std::array<std::int64_t, 4> hello_bytes{};
  std::array<std::int64_t, 4> topology_bytes{};
  std::vector<std::string> lines;
  int beacon_drops = 0;
};

struct Team {
  Team(std::unique_ptr<MobilityModel> mobility, SimTime until) : net(sim, 4, Stack(std::move(mobility))) {
    std::vector<Transport*> robots;
    for (int r = 0; r < 4; ++r) {
      transports.push_back(std::make_unique<SimTransport>(net, NodeId(r)));
      robots.push_back(transports.back().get());
    }
    daemons = LinkStateHelper::Install(net, robots, until);
    channel = net.InternChannel("ALL");
    type = net.InternType("dvpr.test_t");
    for (auto& d : daemons) d->Start();
  }
  NetworkStack Stack(std::unique_ptr<MobilityModel> mobility) {
    NetworkStack s;
    s.mobility = std::move(mobility);
    s.propagation = std::make_unique<RangePropagation>(*s.mobility, 200.0);
    s.access = std::make_unique<RadioLink>(RadioLinkParams{DataRate::Mbps(1), SimTime::Millis(2), 100}, 4);
    auto routing_model = std::make_unique<LinkStateNextHop>(4, LinkStateParams{});
    routing = routing_model.get();
    s.link_state = routing;
    s.next_hop = std::move(routing_model);
    return s;
  }
  // Robot 0's 505-byte message for robot 3 alone, at `at`.
  void ZeroToThreeAt(SimTime at) {
    sim.ScheduleAt(at, [this] {
      const NodeId three[] = {NodeId(3)};
      net.SendTo(NodeId(0), three, channel, type, std::vector<std::uint8_t>(505, 1));
    });
  }
  Simulator sim;
  LinkStateNextHop* routing = nullptr;
  Network net;
  Watch watch;
  ObserverSubscription subscription = net.Subscribe(watch);
  std::vector<std::unique_ptr<SimTransport>> transports;
  std::vector<std::unique_ptr<LinkStateDaemon>> daemons;
  ChannelId channel{};
  MessageTypeId type{};
};

std::unique_ptr<MobilityModel> Chain() {
  return std::make_unique<FixedMobility>(std::vector<Position>{{0, 0, 0}, {150, 0, 0}, {300, 0, 0}, {450, 0, 0}});
}

// The chain 0 - 1 - 2 - 3, 150 m apart. In steady state robots 0 and 3 list 1 link, robots 1
// and 2 list 2. In [10 s, 20 s) each robot sends 5 HELLOs (10, 12, ..., 18 s) and every robot
// sends each of the 4 TCs of the rounds at 10 and 15 s once (the flood through a chain):
//   robot 0: 5 x 63 + 2 x (70 + 72 + 72 + 70) = 315 + 568 = 883 bytes; robot 3 the same;
//   robots 1 and 2: 5 x 65 + 568 = 893 bytes;
//   the team: 3552 bytes in 10 s, 355.2 bytes per second.
TEST(LinkStateDaemon, BeaconsCostTheHandWorkedBytesPerSecond) {
  Team t(Chain(), S(20));
  t.watch.from = S(10);
  t.watch.until = S(20);
  t.sim.Run();
  EXPECT_EQ(t.watch.hello_bytes, (std::array<std::int64_t, 4>{315, 325, 325, 315}));
  EXPECT_EQ(t.watch.topology_bytes, (std::array<std::int64_t, 4>{568, 568, 568, 568}));
  std::int64_t team = 0;
  for (int r = 0; r < 4; ++r) team += t.watch.hello_bytes[static_cast<std::size_t>(r)] + t.watch.topology_bytes[static_cast<std::size_t>(r)];
  EXPECT_EQ(team, 3552);
  // Over the whole run (beacons at 0, 2, ..., 20 s and TCs at 0, 5, ..., 20 s): 11 HELLO rounds
  // of 6 receptions; 5 TC rounds, each origin's TC news to 3 robots and heard again 3 times.
  EXPECT_EQ(t.routing->counters(), (LinkStateNextHop::Counters{.hellos = 66, .topologies = 60, .duplicates = 60}));
  for (const auto& d : t.daemons) {
    EXPECT_EQ(d->counters().hellos, 11u);
    EXPECT_EQ(d->counters().topologies, 5u);
    EXPECT_EQ(d->counters().forwarded, 15u);  // the 3 other origins' TCs, 5 rounds
  }
  EXPECT_EQ(t.watch.beacon_drops, 0);  // link-local: a robot out of range is no destination
}

// Once the TC of 5 s has spread, robot 0 routes to robot 3 over the chain, three hops, to the
// nanosecond of the shortest-path chain (tests/net_models/network/test_radio_chain.cpp): each hop
// 4.376 ms on the air + 2 ms + 500 ns of flight. Before any beacon it has no route.
TEST(LinkStateDaemon, LearnedRoutesCarryAMessageOverTheChain) {
  Team t(Chain(), S(20));
  t.ZeroToThreeAt(S(0));
  t.ZeroToThreeAt(S(13));
  t.sim.Run();
  EXPECT_EQ(t.watch.lines, (std::vector<std::string>{"dropped at 0ns: no_route",
                                                     "delivered at 13019129500ns, 3 hops"}));
}

// Robot 1 drives away at 10.5 s from the middle of a diamond: 0 (0, 0), 1 (150, 0), 2 (150, 120),
// 3 (300, 0). Robot 0 reaches 3 through 1 (the lowest id) or 2 (192.09 m from both). Its table
// keeps 1 until 1's last HELLO (sent at 10 s, heard a few ms later) is 6 s old: a message at
// 15.9 s still goes to 1 and is lost as a stale route; at 16.1 s the route goes through 2 and
// arrives after two hops of 4.376 ms + 2 ms + 641 ns (192.09 m at the speed of light):
// 16.1 s + 2 x 6 376 641 ns = 16 112 753 282 ns.
TEST(LinkStateDaemon, ARouteThroughARobotThatLeftIsUsedUntilItsHelloExpiresThenRepaired) {
  std::vector<std::vector<Waypoint>> tracks = {
      {{S(0), {0, 0, 0}}},
      {{S(0), {150, 0, 0}}, {S(10.5), {150, 0, 0}}, {S(10.6), {150, 0, -2000}}},
      {{S(0), {150, 0, 120}}},
      {{S(0), {300, 0, 0}}},
  };
  Team t(std::make_unique<TrackMobility>(std::move(tracks)), S(30));
  t.ZeroToThreeAt(S(9));
  t.ZeroToThreeAt(S(15.9));
  t.ZeroToThreeAt(S(16.1));
  t.sim.Run();
  EXPECT_EQ(t.watch.lines, (std::vector<std::string>{"delivered at 9012753000ns, 2 hops",
                                                     "dropped at 15900000000ns: stale_route",
                                                     "delivered at 16112753282ns, 2 hops"}));
}

// The helper installs a daemon per robot only where the next hop is link_state, and on one
// transport per robot.
TEST(LinkStateHelper, InstallsOnlyOnLinkStateAndOnlyOneDaemonPerRobot) {
  Simulator sim;
  NetworkStack direct;
  direct.access = std::make_unique<RadioLink>(RadioLinkParams{DataRate::Mbps(1), SimTime::Millis(2), 100}, 2);
  Network plain(sim, 2, std::move(direct));
  SimTransport a(plain, NodeId(0)), b(plain, NodeId(1));
  std::vector<Transport*> both{&a, &b};
  EXPECT_TRUE(LinkStateHelper::Install(plain, both, S(10)).empty());
  EXPECT_FALSE(plain.link_state());

  Team t(Chain(), S(20));
  std::vector<Transport*> three{t.transports[0].get(), t.transports[1].get(), t.transports[2].get()};
  try {
    (void)LinkStateHelper::Install(t.net, three, S(20));
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "LinkStateHelper: 3 transports for 4 nodes");
  }
  EXPECT_EQ(t.daemons.size(), 4U);
}

}  // namespace
}  // namespace dvpr
