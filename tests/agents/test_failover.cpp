// Failover's pure parts, on tables small enough to work every distance by hand: which robot
// succeeds a lost one for a query (agents/placement/failover_placement.h) and when a silent robot is
// declared lost (agents/placement/failure_detector.h).
#include <optional>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "agents/placement/failover_placement.h"
#include "tests/descriptor_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Robots;

// Four centroids in the plane: c0 = (0, 0) of robot 0, c1 = (10, 0) of robot 1, c2 = (0, 10)
// and c3 = (6, 0) both of robot 2.
class SuccessorTest : public ::testing::Test {
 protected:
  SuccessorTest() {
    CentroidMatrix c(4, 2);
    c << 0, 0, 10, 0, 0, 10, 6, 0;
    table_ = std::make_shared<const CentroidTable>(c, Robots({0, 1, 2, 2}), 3);
  }
  std::shared_ptr<const CentroidTable> table_;
  const std::vector<bool> none_{false, false, false};
  const std::vector<bool> robot2_{false, false, true};
};

// q = (7, 1): distances to c0..c3 are sqrt(50) = 7.07, sqrt(10) = 3.16, sqrt(130) = 11.40,
// sqrt(2) = 1.41. Nearest c3 (robot 2); without robot 2 (c2, c3) the nearest is c1: robot 1;
// without robots 1 and 2 it is c0: robot 0; with all lost there is none.
TEST_F(SuccessorTest, NextNearestCentroidOfALiveRobot) {
  const float q[2] = {7, 1};
  EXPECT_EQ(SuccessorOf(*table_, none_, q), RobotId(2));
  EXPECT_EQ(SuccessorOf(*table_, robot2_, q), RobotId(1));
  EXPECT_EQ(SuccessorOf(*table_, {false, true, true}, q), RobotId(0));
  EXPECT_EQ(SuccessorOf(*table_, {true, true, true}, q), std::nullopt);
}

// q = (1, 6): distances sqrt(37) = 6.08, sqrt(117) = 10.82, sqrt(17) = 4.12, sqrt(61) = 7.81.
// Nearest c2 (robot 2); without robot 2 it is c0: robot 0. So robot 2's two clusters pass to
// two different robots: near c3 to robot 1 (above), near c2 to robot 0.
TEST_F(SuccessorTest, ALostRobotsClustersAreDividedAmongItsNeighbours) {
  const float q[2] = {1, 6};
  EXPECT_EQ(SuccessorOf(*table_, none_, q), RobotId(2));
  EXPECT_EQ(SuccessorOf(*table_, robot2_, q), RobotId(0));
}

TEST_F(SuccessorTest, FailOverReplacesLostRobotsOnceInPlace) {
  const float q[2] = {7, 1};  // successor of robot 2: robot 1
  const PlacementDecision d{Robots({2, 0}), Robots({2})};
  const PlacementDecision f = FailOver(d, table_.get(), robot2_, q);
  EXPECT_EQ(f.search_at, Robots({1, 0}));
  EXPECT_EQ(f.store_at, Robots({1}));
  // A successor already asked is asked once.
  const PlacementDecision g = FailOver(PlacementDecision{Robots({2, 1}), Robots({2, 1})}, table_.get(), robot2_, q);
  EXPECT_EQ(g.search_at, Robots({1}));
  EXPECT_EQ(g.store_at, Robots({1}));
  // Nothing lost: unchanged.
  const PlacementDecision h = FailOver(d, table_.get(), none_, q);
  EXPECT_EQ(h.search_at, d.search_at);
  EXPECT_EQ(h.store_at, d.store_at);
}

TEST_F(SuccessorTest, BroadcastHasNoTableSoALostRobotIsNoLongerAsked) {
  const float q[2] = {7, 1};
  const PlacementDecision f = FailOver(PlacementDecision{Robots({0, 1, 2}), Robots({0})}, nullptr, {false, true, false}, q);
  EXPECT_EQ(f.search_at, Robots({0, 2}));
  EXPECT_EQ(f.store_at, Robots({0}));
}

// Robot 0 watches robots 1 and 2 with a 1 s timeout from t = 0: robot 1 last heard at 0.5 s,
// robot 2 at 0.2 s. At 1.1 s both are within 1 s (0.6 and 0.9); at 1.3 s robot 2 has been silent
// 1.1 s; at 1.6 s robot 1 has (1.1 s). A heartbeat after that does not bring it back.
TEST(FailureDetector, DeclaresSilentRobotsLostOnceAndForGood) {
  FailureDetector d(RobotId(0), 3, SimTime::Seconds(1), SimTime::Zero());
  d.Heard(RobotId(1), SimTime::Millis(500));
  d.Heard(RobotId(2), SimTime::Millis(200));
  EXPECT_TRUE(d.Check(SimTime::Millis(1100)).empty());
  EXPECT_EQ(d.Check(SimTime::Millis(1300)), Robots({2}));
  EXPECT_EQ(d.Check(SimTime::Millis(1600)), Robots({1}));
  d.Heard(RobotId(1), SimTime::Millis(1700));
  EXPECT_TRUE(d.Check(SimTime::Millis(1700)).empty());
  EXPECT_FALSE(d.IsLive(RobotId(1)));
  EXPECT_TRUE(d.IsLive(RobotId(0)));  // never itself, however long
  EXPECT_TRUE(d.Check(SimTime::Seconds(100)).empty());
  const std::vector<LostRobot> expected{{RobotId(2), SimTime::Millis(1300)}, {RobotId(1), SimTime::Millis(1600)}};
  EXPECT_EQ(d.lost(), expected);
}

// Exactly the timeout of silence is not yet lost: only longer is.
TEST(FailureDetector, ExactlyTheTimeoutIsNotYetLost) {
  FailureDetector d(RobotId(1), 2, SimTime::Millis(100), SimTime::Millis(50));
  EXPECT_TRUE(d.Check(SimTime::Millis(150)).empty());
  EXPECT_EQ(d.Check(SimTime::Millis(151)), Robots({0}));
}

TEST(FailoverParams, TimeoutMustExceedThePeriod) {
  FailoverParams p;
  EXPECT_NO_THROW(p.Validate());
  p.timeout = p.heartbeat_period;
  EXPECT_THROW(p.Validate(), std::invalid_argument);
  p = FailoverParams{};
  p.heartbeat_period = SimTime::Zero();
  EXPECT_THROW(p.Validate(), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
