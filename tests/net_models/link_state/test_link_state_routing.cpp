// link_state routing's tables (net_models/link_state/link_state_routing.h), fed by hand as the robots'
// beacons would feed them: what a robot advertises, which TC is news, the routes it takes, and
// when what it heard is forgotten (OLSR's hold times: 3 HELLO periods, 3 TC periods).
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "net_models/link_state/link_state_routing.h"

namespace dvpr {
namespace {

using Nodes = std::vector<NodeId>;

SimTime S(double s) { return SimTime::Nanos(static_cast<std::int64_t>(s * 1e9)); }

// The next hops from `at` to every other robot of 0..n-1, -1 for no route.
std::vector<int> HopsFrom(LinkStateNextHop& r, int at, SimTime now) {
  Nodes dsts;
  for (int v = 0; v < r.nodes(); ++v) {
    if (v != at) dsts.push_back(NodeId(v));
  }
  Nodes hops(dsts.size());
  r.NextHops(NodeId(at), dsts, now, r.nodes(), hops);
  std::vector<int> out;
  for (const NodeId h : hops) out.push_back(h.value);
  return out;
}

TEST(LinkStateNextHop, ANeighbourIsUsedOnlyOnceItsHelloListsTheReceiver) {
  LinkStateNextHop r(3, LinkStateParams{});
  r.OnHello(NodeId(0), NodeId(1), Nodes{}, S(0.001));  // 1 has heard nobody yet
  EXPECT_EQ(HopsFrom(r, 0, S(1)), (std::vector<int>{-1, -1}));
  EXPECT_EQ(r.HelloLinks(NodeId(0), S(1)), Nodes{NodeId(1)});  // heard: advertised in 0's HELLO
  EXPECT_TRUE(r.TopologyLinks(NodeId(0), S(1)).empty());       // but not symmetric: not in its TC
  r.OnHello(NodeId(0), NodeId(1), Nodes{NodeId(0), NodeId(2)}, S(2.001));
  // 1 is a symmetric neighbour, 2 a two-hop neighbour through it.
  EXPECT_EQ(HopsFrom(r, 0, S(3)), (std::vector<int>{1, 1}));
  EXPECT_EQ(r.TopologyLinks(NodeId(0), S(3)), Nodes{NodeId(1)});
}

TEST(LinkStateNextHop, ATopologyMessageIsNewsOnceAndExtendsTheRoutes) {
  LinkStateNextHop r(5, LinkStateParams{});
  r.OnHello(NodeId(0), NodeId(1), Nodes{NodeId(0), NodeId(2)}, S(2));
  EXPECT_EQ(HopsFrom(r, 0, S(3)), (std::vector<int>{1, 1, -1, -1}));
  // 2's TC says 2 - 3; 3's says 3 - 4.
  EXPECT_TRUE(r.OnTopology(NodeId(0), NodeId(2), 1, Nodes{NodeId(1), NodeId(3)}, S(5)));
  EXPECT_EQ(HopsFrom(r, 0, S(5)), (std::vector<int>{1, 1, 1, -1}));
  EXPECT_TRUE(r.OnTopology(NodeId(0), NodeId(3), 1, Nodes{NodeId(2), NodeId(4)}, S(5)));
  EXPECT_EQ(HopsFrom(r, 0, S(5)), (std::vector<int>{1, 1, 1, 1}));
  // The same TC again, an older one, and robot 0's own coming back: duplicates, not forwarded.
  EXPECT_FALSE(r.OnTopology(NodeId(0), NodeId(2), 1, Nodes{NodeId(1), NodeId(3)}, S(5)));
  EXPECT_FALSE(r.OnTopology(NodeId(0), NodeId(2), 0, Nodes{}, S(5)));
  EXPECT_EQ(r.NextSequence(NodeId(0)), 1u);
  EXPECT_FALSE(r.OnTopology(NodeId(0), NodeId(0), 1, Nodes{NodeId(1)}, S(5)));
  EXPECT_EQ(r.counters(), (LinkStateNextHop::Counters{.hellos = 1, .topologies = 2, .duplicates = 3}));
  // A newer TC from 3 that no longer lists 4: 4 has no route (1's HELLO heard again at 9 s).
  r.OnHello(NodeId(0), NodeId(1), Nodes{NodeId(0), NodeId(2)}, S(9));
  EXPECT_TRUE(r.OnTopology(NodeId(0), NodeId(3), 2, Nodes{NodeId(2)}, S(10)));
  EXPECT_EQ(HopsFrom(r, 0, S(10)), (std::vector<int>{1, 1, 1, -1}));
}

TEST(LinkStateNextHop, TiesGoToTheLowestNeighbour) {
  LinkStateNextHop r(4, LinkStateParams{});
  // 0 hears 1 and 2, both of which hear 3.
  r.OnHello(NodeId(0), NodeId(2), Nodes{NodeId(0), NodeId(3)}, S(2));
  r.OnHello(NodeId(0), NodeId(1), Nodes{NodeId(0), NodeId(3)}, S(2));
  EXPECT_EQ(HopsFrom(r, 0, S(3)), (std::vector<int>{1, 2, 1}));
}

// A HELLO is kept 3 x 2 s = 6 s after it was heard, a TC 3 x 5 s = 15 s.
TEST(LinkStateNextHop, WhatWasHeardIsForgottenAfterItsHoldTime) {
  LinkStateNextHop r(4, LinkStateParams{});
  r.OnHello(NodeId(0), NodeId(1), Nodes{NodeId(0)}, S(10));
  r.OnTopology(NodeId(0), NodeId(1), 1, Nodes{NodeId(0), NodeId(2)}, S(10));
  EXPECT_EQ(HopsFrom(r, 0, S(16) - SimTime::Nanos(1)), (std::vector<int>{1, 1, -1}));
  EXPECT_EQ(HopsFrom(r, 0, S(16)), (std::vector<int>{-1, -1, -1}));  // 1 forgotten: no way to 2 either
  // A fresh HELLO from 1 brings back both; the TC is kept until 25 s.
  r.OnHello(NodeId(0), NodeId(1), Nodes{NodeId(0)}, S(20));
  EXPECT_EQ(HopsFrom(r, 0, S(25) - SimTime::Nanos(1)), (std::vector<int>{1, 1, -1}));
  EXPECT_EQ(HopsFrom(r, 0, S(25)), (std::vector<int>{1, -1, -1}));
  EXPECT_EQ(r.HelloLinks(NodeId(0), S(26) - SimTime::Nanos(1)), Nodes{NodeId(1)});
  EXPECT_TRUE(r.HelloLinks(NodeId(0), S(26)).empty());
}

TEST(LinkStateNextHop, ShorterPeriodsShortenTheHoldTimes) {
  LinkStateNextHop r(2, LinkStateParams{.hello = SimTime::Millis(500), .topology = SimTime::Millis(1000)});
  r.OnHello(NodeId(0), NodeId(1), Nodes{NodeId(0)}, S(1));
  EXPECT_EQ(HopsFrom(r, 0, S(2.5) - SimTime::Nanos(1)), (std::vector<int>{1}));
  EXPECT_EQ(HopsFrom(r, 0, S(2.5)), (std::vector<int>{-1}));
}

TEST(LinkStateNextHop, LinksOutsideTheTeamAreIgnoredAndBadNodesThrow) {
  LinkStateNextHop r(3, LinkStateParams{});
  r.OnHello(NodeId(0), NodeId(1), Nodes{NodeId(0), NodeId(7), NodeId(-2), NodeId(1)}, S(1));
  EXPECT_EQ(HopsFrom(r, 0, S(1)), (std::vector<int>{1, -1}));
  EXPECT_THROW(r.OnHello(NodeId(0), NodeId(3), Nodes{}, S(1)), std::out_of_range);
  EXPECT_THROW(r.OnTopology(NodeId(-1), NodeId(1), 1, Nodes{}, S(1)), std::out_of_range);
  EXPECT_THROW(LinkStateNextHop(0, LinkStateParams{}), std::invalid_argument);
  EXPECT_THROW(LinkStateNextHop(2, LinkStateParams{.hello = SimTime::Zero()}), std::invalid_argument);
  EXPECT_EQ(r.UnheardHop(), DropReason::kStaleRoute);
  EXPECT_EQ(r.Name(), "link_state");
  EXPECT_EQ(ParseNextHopKind("link_state"), NextHopKind::kLinkState);
  EXPECT_EQ(ToString(NextHopKind::kLinkState), "link_state");
}

}  // namespace
}  // namespace dvpr
