// ShortestPathNextHop (net_models/routing/shortest_path_routing.h) on hand-made teams whose graph is
// drawn in each test: first hops of shortest paths, ties to the lowest id, no route, and the
// graph taken once per refresh window.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

#include "net_models/mobility/fixed_mobility.h"
#include "net_models/mobility/track_mobility.h"
#include "net_models/routing/shortest_path_routing.h"

namespace dvpr {
namespace {

// Hears within 50 m along x; counts the questions it is asked.
class FiftyMetres final : public PropagationModel {
 public:
  explicit FiftyMetres(const MobilityModel& mobility) : mobility_(mobility) {}
  int questions = 0;

 private:
  void DoReach(NodeId src, std::span<const NodeId> receivers, SimTime now, std::span<Reception> out) override {
    ++questions;
    for (std::size_t i = 0; i < receivers.size(); ++i) {
      out[i].reaches = std::abs(mobility_.PositionOf(src, now).x - mobility_.PositionOf(receivers[i], now).x) <= 50.0;
    }
  }
  std::string_view DoName() const override { return "fifty"; }
  const MobilityModel& mobility_;
};

std::vector<NodeId> Hops(NextHopRouting& routing, int at, std::vector<NodeId> dsts, SimTime now, int nodes) {
  std::vector<NodeId> hops(dsts.size());
  routing.NextHops(NodeId(at), dsts, now, nodes, hops);
  return hops;
}

FixedMobility AtX(const std::vector<double>& xs) {
  std::vector<Position> p;
  for (const double x : xs) p.push_back(Position{x, 0, 0});
  return FixedMobility(p);
}

TEST(ShortestPathNextHop, AChainIsRelayedHopByHop) {
  // 0 - 1 - 2 - 3, 40 m apart: each hears only its neighbours.
  const FixedMobility m = AtX({0, 40, 80, 120});
  FiftyMetres air(m);
  ShortestPathNextHop r(air, 4);
  EXPECT_EQ(r.Name(), "shortest_path");
  EXPECT_EQ(Hops(r, 0, {NodeId(1), NodeId(2), NodeId(3)}, SimTime::Zero(), 4),
            (std::vector<NodeId>{NodeId(1), NodeId(1), NodeId(1)}));
  EXPECT_EQ(Hops(r, 1, {NodeId(3), NodeId(0)}, SimTime::Zero(), 4), (std::vector<NodeId>{NodeId(2), NodeId(0)}));
  EXPECT_EQ(Hops(r, 3, {NodeId(0)}, SimTime::Zero(), 4), (std::vector<NodeId>{NodeId(2)}));
}

TEST(ShortestPathNextHop, TiesGoToTheLowestIdAndTheUnreachableHaveNoRoute) {
  // 0 at 0; 1 and 2 both at 30 (both hear 0 and 3); 3 at 60; 4 far away.
  const FixedMobility m = AtX({0, 30, 30, 60, 1000});
  FiftyMetres air(m);
  ShortestPathNextHop r(air, 5);
  EXPECT_EQ(Hops(r, 0, {NodeId(3), NodeId(4)}, SimTime::Zero(), 5), (std::vector<NodeId>{NodeId(1), kNoRoute}));
  EXPECT_EQ(Hops(r, 4, {NodeId(0)}, SimTime::Zero(), 5), (std::vector<NodeId>{kNoRoute}));
}

TEST(ShortestPathNextHop, TheGraphIsTakenOncePerRefreshWindow) {
  // Node 1 stands at 40 m until 1 s, then drives off to 1040 m at 2 s.
  const TrackMobility m({{{SimTime::Zero(), {0, 0, 0}}},
                         {{SimTime::Seconds(1), {40, 0, 0}}, {SimTime::Seconds(2), {1040, 0, 0}}}});
  FiftyMetres air(m);
  ShortestPathNextHop r(air, 2, SimTime::Millis(500));
  EXPECT_EQ(Hops(r, 0, {NodeId(1)}, SimTime::Millis(100), 2), (std::vector<NodeId>{NodeId(1)}));
  EXPECT_EQ(air.questions, 2);  // one per sender, at the window's start
  EXPECT_EQ(Hops(r, 1, {NodeId(0)}, SimTime::Millis(499), 2), (std::vector<NodeId>{NodeId(0)}));
  EXPECT_EQ(air.questions, 2);  // same window: no new question
  // Window [1 s, 1.5 s) is taken at 1 s, when node 1 is still at 40 m: its route stands until
  // the next window even though node 1 is 240 m away at 1.2 s.
  EXPECT_EQ(Hops(r, 0, {NodeId(1)}, SimTime::Millis(1200), 2), (std::vector<NodeId>{NodeId(1)}));
  EXPECT_EQ(Hops(r, 0, {NodeId(1)}, SimTime::Millis(1500), 2), (std::vector<NodeId>{kNoRoute}));
  EXPECT_EQ(air.questions, 6);
}

TEST(ShortestPathNextHop, RefusesNoNodeAndARefreshThatIsNotPositive) {
  const FixedMobility m = AtX({0});
  FiftyMetres air(m);
  EXPECT_THROW(ShortestPathNextHop(air, 0), std::invalid_argument);
  EXPECT_THROW(ShortestPathNextHop(air, 1, SimTime::Zero()), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
