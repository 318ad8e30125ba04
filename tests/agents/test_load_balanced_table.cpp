// Load-aware centroid-to-robot tables: LPT bin packing and bounded loads, on hand-made cluster
// loads whose packings are worked out by hand in the comments.
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "agents/algorithms/load_balanced_table.h"
#include "tests/descriptor_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Robots;

TEST(AssignByLoad, LptGivesTheLargestClusterToTheLeastLoadedRobot) {
  // Graham's classic: 3 3 2 2 2 on two robots. 3->r0, 3->r1, 2->r0 (tie, lowest id), 2->r1,
  // 2->r0: loads 7 and 5 (the optimum is 6 and 6; LPT is within 4/3).
  EXPECT_EQ(AssignByLoad({3, 3, 2, 2, 2}, 2, {.epsilon = -1}), Robots({0, 1, 0, 1, 0}));
  // One hot cluster of 8 and eight of 1: the hot one alone on r0, all the small ones on r1.
  EXPECT_EQ(AssignByLoad({1, 1, 8, 1, 1, 1, 1, 1, 1}, 2, {.epsilon = -1}), Robots({1, 1, 0, 1, 1, 1, 1, 1, 1}));
}

TEST(AssignByLoad, BoundedLoadsKeepRoundRobinWhileItFits) {
  // Equal loads fit round robin exactly (capacity 2 with epsilon 0): the paper's table.
  EXPECT_EQ(AssignByLoad({1, 1, 1, 1}, 2, {.epsilon = 0}), Robots({0, 1, 0, 1}));
}

TEST(AssignByLoad, BoundedLoadsMoveOverflowingClustersToTheNextRobotInRingOrder) {
  // Loads 6 1 5 1 1 0 on two robots, epsilon 0: capacity 7. In load order: c0 (6) -> r0 = 6;
  // c2 (5) prefers r0 but 11 > 7 -> r1 = 5; c1 -> r1 = 6; c3 -> r1 = 7 (fits exactly);
  // c4 -> r0 = 7; c5 (0) -> r1. Round robin would have put 12 on r0.
  EXPECT_EQ(AssignByLoad({6, 1, 5, 1, 1, 0}, 2, {.epsilon = 0}), Robots({0, 1, 1, 1, 0, 1}));
  // A cluster larger than the capacity fits nowhere: it goes to the least loaded robot.
  EXPECT_EQ(AssignByLoad({10, 1}, 2, {.epsilon = 0}), Robots({0, 1}));
  // With room to spare (epsilon 1: capacity 14) the round-robin owners stay.
  EXPECT_EQ(AssignByLoad({6, 1, 5, 1, 1, 0}, 2, {.epsilon = 1}), Robots({0, 1, 0, 1, 0, 1}));
}

TEST(AssignByLoad, RejectsBadInput) {
  EXPECT_THROW(AssignByLoad({1, -1}, 2, {}), std::invalid_argument);
  EXPECT_THROW(AssignByLoad({1, 1}, 0, {}), std::invalid_argument);
  EXPECT_THROW(AssignByLoad({1, 1}, 2, {.epsilon = std::nan("")}), std::invalid_argument);
}

TEST(ExpectedLoads, CountsSampleDescriptorsPerNearestCentroid) {
  CentroidMatrix c(3, 1);
  c << 0, 10, 20;
  DescriptorMatrix sample(5, 1);
  sample << 1, 2, 9, 5, 30;  // nearest 0, 0, 1, tie 0|1 -> 0, 2
  EXPECT_EQ(ExpectedLoads(c, sample), (std::vector<double>{3, 1, 1}));
  EXPECT_EQ(ExpectedLoads(c, sample, 0.5), (std::vector<double>{3.5, 1.5, 1.5}));
}

TEST(LoadBalancedTable, SpreadsTheClustersTheSampleCrowds) {
  // Four centroids, the sample crowds the first two (3 each), the others get only the prior 1.
  // LPT with loads 4 4 1 1: c0 -> r0, c1 -> r1, c2 -> r0, c3 -> r1. Round robin on two robots
  // would be the same here, so use three robots: c0 -> r0, c1 -> r1, c2 -> r2, c3 -> r2.
  CentroidMatrix c(4, 1);
  c << 0, 10, 20, 30;
  DescriptorMatrix sample(6, 1);
  sample << 0, 1, -1, 10, 11, 9;
  const CentroidTable t = LoadBalancedTable(c, sample, 3, {.epsilon = -1});
  EXPECT_EQ(t.OwnerOf(0), RobotId(0));
  EXPECT_EQ(t.OwnerOf(1), RobotId(1));
  EXPECT_EQ(t.OwnerOf(2), RobotId(2));
  EXPECT_EQ(t.OwnerOf(3), RobotId(2));
}

}  // namespace
}  // namespace dvpr
