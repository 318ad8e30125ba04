// The mobility models (net_models/mobility/fixed_mobility.h, track_mobility.h): positions worked out by
// hand from the waypoints.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "net_models/mobility/fixed_mobility.h"
#include "net_models/mobility/track_mobility.h"

namespace dvpr {
namespace {

std::string ErrorOf(auto&& make) {
  try {
    make();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(FixedMobility, EveryNodeStaysWhereItIsPut) {
  const FixedMobility m({Position{1, 2, 3}, Position{4, 6, 3}});
  EXPECT_EQ(m.nodes(), 2);
  EXPECT_EQ(m.Name(), "fixed");
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Zero()), (Position{1, 2, 3}));
  EXPECT_EQ(m.PositionOf(NodeId(1), SimTime::Seconds(1000)), (Position{4, 6, 3}));
  // (3, 4, 0) apart: 5 m.
  EXPECT_DOUBLE_EQ(Distance(m.PositionOf(NodeId(0), SimTime::Zero()), m.PositionOf(NodeId(1), SimTime::Zero())), 5.0);
}

TEST(FixedMobility, AtOriginPlacesEveryNodeAtZero) {
  const FixedMobility m = FixedMobility::AtOrigin(3);
  EXPECT_EQ(m.nodes(), 3);
  EXPECT_EQ(m.PositionOf(NodeId(2), SimTime::Millis(7)), (Position{0, 0, 0}));
}

TEST(FixedMobility, RefusesNoNodeANonFinitePositionAndAnUnknownNode) {
  EXPECT_EQ(ErrorOf([] { FixedMobility m({}); }), "positions: a network needs at least one node, got none");
  EXPECT_EQ(ErrorOf([] { FixedMobility::AtOrigin(0); }), "nodes: a network needs at least one node, got 0");
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ErrorOf([&] { FixedMobility m({Position{}, Position{0, inf, 1}}); }),
            "positions[1]: a position must be finite, got (0, inf, 1)");
  const FixedMobility m({Position{}});
  EXPECT_THROW(m.PositionOf(NodeId(1), SimTime::Zero()), std::out_of_range);
  EXPECT_THROW(m.PositionOf(NodeId(-1), SimTime::Zero()), std::out_of_range);
}

// Node 0 drives 10 m along x in the first second, then 20 m along z in the next two; node 1
// starts at t = 1 s and drives 4 m back along y in 4 s.
class TrackMobilityTest : public ::testing::Test {
 protected:
  TrackMobility m{{{{SimTime::Zero(), {0, 0, 0}}, {SimTime::Seconds(1), {10, 0, 0}}, {SimTime::Seconds(3), {10, 0, 20}}},
                   {{SimTime::Seconds(1), {0, 4, 0}}, {SimTime::Seconds(5), {0, 0, 0}}}}};
};

TEST_F(TrackMobilityTest, InterpolatesLinearlyBetweenWaypoints) {
  EXPECT_EQ(m.Name(), "track");
  EXPECT_EQ(m.nodes(), 2);
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Millis(250)), (Position{2.5, 0, 0}));
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Seconds(2)), (Position{10, 0, 10}));
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Millis(2500)), (Position{10, 0, 15}));
  EXPECT_EQ(m.PositionOf(NodeId(1), SimTime::Seconds(2)), (Position{0, 3, 0}));
}

TEST_F(TrackMobilityTest, IsAtAWaypointAtItsTime) {
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Zero()), (Position{0, 0, 0}));
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Seconds(1)), (Position{10, 0, 0}));
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Seconds(3)), (Position{10, 0, 20}));
}

TEST_F(TrackMobilityTest, WaitsAtItsFirstWaypointAndStaysWhereItStopped) {
  EXPECT_EQ(m.PositionOf(NodeId(1), SimTime::Zero()), (Position{0, 4, 0}));
  EXPECT_EQ(m.PositionOf(NodeId(1), SimTime::Millis(999)), (Position{0, 4, 0}));
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Seconds(3) + SimTime::Nanos(1)), (Position{10, 0, 20}));
  EXPECT_EQ(m.PositionOf(NodeId(1), SimTime::Seconds(3600)), (Position{0, 0, 0}));
}

TEST_F(TrackMobilityTest, AskingChangesNothing) {
  const Position later = m.PositionOf(NodeId(0), SimTime::Seconds(2));
  const Position earlier = m.PositionOf(NodeId(0), SimTime::Millis(500));
  EXPECT_EQ(earlier, (Position{5, 0, 0}));
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Seconds(2)), later);
  EXPECT_THROW(m.PositionOf(NodeId(2), SimTime::Zero()), std::out_of_range);
}

TEST(TrackMobility, OneWaypointIsAFixedNode) {
  const TrackMobility m({{{SimTime::Seconds(2), {7, 8, 9}}}});
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Zero()), (Position{7, 8, 9}));
  EXPECT_EQ(m.PositionOf(NodeId(0), SimTime::Seconds(9)), (Position{7, 8, 9}));
}

TEST(TrackMobility, RefusesEmptyTracksTimesThatDoNotIncreaseAndNonFinitePositions) {
  EXPECT_EQ(ErrorOf([] { TrackMobility m({}); }), "tracks: a network needs at least one node, got none");
  EXPECT_EQ(ErrorOf([] { TrackMobility m({{{SimTime::Zero(), {}}}, {}}); }),
            "tracks[1]: a node's track needs at least one waypoint, got none");
  EXPECT_EQ(ErrorOf([] {
              TrackMobility m({{{SimTime::Zero(), {}}, {SimTime::Seconds(1), {}}, {SimTime::Seconds(1), {1, 0, 0}}}});
            }),
            "tracks[0][2].at: waypoint times must strictly increase, got 1s after 1s");
  EXPECT_EQ(ErrorOf([] { TrackMobility m({{{SimTime::Millis(5), {}}, {SimTime::Millis(4), {}}}}); }),
            "tracks[0][1].at: waypoint times must strictly increase, got 4ms after 5ms");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(ErrorOf([&] { TrackMobility m({{{SimTime::Zero(), {nan, 0, 0}}}}); }),
            "tracks[0][0].where: a position must be finite, got (nan, 0, 0)");
}

}  // namespace
}  // namespace dvpr
