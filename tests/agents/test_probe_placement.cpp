// Routing decisions of multi-probe (FAISS nprobe, SPANN adaptive pruning) and boundary replication
// on centroids on a line, where every distance can be read off by hand.
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "agents/placement/probe_placement.h"
#include "tests/descriptor_support.h"

namespace dvpr {
namespace {

using dvpr::testing_support::Robots;

// Centroids at 0, 10, 20, 30 owned by robots 0, 1, 2, 0.
class ProbePlacementTest : public ::testing::Test {
 protected:
  ProbePlacementTest() {
    CentroidMatrix c(4, 1);
    c << 0, 10, 20, 30;
    table_ = std::make_shared<const CentroidTable>(c, Robots({0, 1, 2, 0}), 3);
  }
  std::shared_ptr<const CentroidTable> table_;
};

TEST_F(ProbePlacementTest, RankCentroidsByDistanceTiesByIndex) {
  const float x = 15;  // distances 15, 5, 5, 15
  const auto ranked = RankCentroids(*table_, &x);
  ASSERT_EQ(ranked.size(), 4u);
  EXPECT_EQ(ranked[0], std::make_pair(5.0, 1));
  EXPECT_EQ(ranked[1], std::make_pair(5.0, 2));
  EXPECT_EQ(ranked[2], std::make_pair(15.0, 0));
  EXPECT_EQ(ranked[3], std::make_pair(15.0, 3));
}

TEST_F(ProbePlacementTest, FixedProbesSearchTheOwnersOfTheMNearestAndStoreAtTheNearest) {
  MultiProbePlacement two(table_, {.probes = 2, .epsilon = -1});
  const float near_start = 4;  // distances 4, 6, 16, 26
  PlacementDecision d = two.Route(RobotId(2), &near_start);
  EXPECT_EQ(d.search_at, Robots({0, 1}));
  EXPECT_EQ(d.store_at, Robots({0}));
  const float near_end = 26;  // distances 26, 16, 6, 4: centroids 3 (robot 0), 2 (robot 2)
  d = two.Route(RobotId(1), &near_end);
  EXPECT_EQ(d.search_at, Robots({0, 2}));
  EXPECT_EQ(d.store_at, Robots({0}));
  MultiProbePlacement three(table_, {.probes = 3, .epsilon = -1});
  EXPECT_EQ(three.Route(RobotId(1), &near_end).search_at, Robots({0, 2, 1}));
  // Four probes reach all centroids, but robot 0 owns two of them: three robots, no duplicate.
  MultiProbePlacement four(table_, {.probes = 4, .epsilon = -1});
  EXPECT_EQ(four.Route(RobotId(1), &near_start).search_at, Robots({0, 1, 2}));
}

TEST_F(ProbePlacementTest, FixedProbesStillProbeMWhenTheDescriptorSitsOnACentroid) {
  // Nearest distance 0: a relative bound (1 + eps) x 0 must not cut the fixed-m probes.
  MultiProbePlacement two(table_, {.probes = 2, .epsilon = -1});
  const float on_centroid = 10;  // distances 10, 0, 10, 20
  EXPECT_EQ(two.Route(RobotId(0), &on_centroid).search_at, Robots({1, 0}));
}

TEST_F(ProbePlacementTest, AdaptiveProbesOnlyCentroidsWithinOnePlusEpsilon) {
  const float x = 4;  // distances 4, 6, 16, 26: 6 / 4 = 1.5
  MultiProbePlacement tight(table_, {.probes = 4, .epsilon = 0.4});
  MultiProbePlacement loose(table_, {.probes = 4, .epsilon = 0.6});
  EXPECT_EQ(tight.Route(RobotId(2), &x).search_at, Robots({0}));
  EXPECT_EQ(loose.Route(RobotId(2), &x).search_at, Robots({0, 1}));
  EXPECT_EQ(loose.Route(RobotId(2), &x).store_at, Robots({0}));
  // The cap still holds: one probe however loose epsilon is.
  MultiProbePlacement capped(table_, {.probes = 1, .epsilon = 10});
  EXPECT_EQ(capped.Route(RobotId(2), &x).search_at, Robots({0}));
  // A tie at the border (15: 5 and 5) probes both owners even with epsilon 0.
  MultiProbePlacement exact(table_, {.probes = 4, .epsilon = 0});
  const float border = 15;
  EXPECT_EQ(exact.Route(RobotId(0), &border).search_at, Robots({1, 2}));
}

TEST_F(ProbePlacementTest, ReplicationStoresAtBorderOwnersAndSearchesOnlyTheNearest) {
  BoundaryReplicationPlacement r(table_, {.epsilon = 0.6, .max_replicas = 3});
  const float x = 4;  // distances 4, 6 (within 1.6 x 4), 16, 26
  PlacementDecision d = r.Route(RobotId(2), &x);
  EXPECT_EQ(d.search_at, Robots({0}));
  EXPECT_EQ(d.store_at, Robots({0, 1}));
  // On the wire: robot 0 is asked to search and store, robot 1 only to keep a replica; the
  // querying robot 2 neither searches nor stores its own frame.
  const QueryPlan from_2 = PlanOf(d, RobotId(2), r.UsesBroadcastChannel());
  EXPECT_EQ(from_2.channels, (std::vector<std::string>{"DVPR_QUERY_0", "DVPR_STORE_1"}));
  EXPECT_FALSE(from_2.search_here);
  EXPECT_FALSE(from_2.store_here);
  EXPECT_EQ(from_2.searches, 1);
  // Deep inside a cluster (1: distances 1, 9, ...) nothing is replicated.
  const float inside = 1;
  EXPECT_EQ(r.Route(RobotId(2), &inside).store_at, Robots({0}));
  // max_replicas caps the copies.
  BoundaryReplicationPlacement single(table_, {.epsilon = 0.6, .max_replicas = 1});
  EXPECT_EQ(single.Route(RobotId(2), &x).store_at, Robots({0}));
}

TEST_F(ProbePlacementTest, ParamsAreValidated) {
  EXPECT_THROW(MultiProbePlacement r(table_, {.probes = 0, .epsilon = -1}), std::invalid_argument);
  EXPECT_THROW(BoundaryReplicationPlacement r(table_, {.epsilon = -0.1, .max_replicas = 2}), std::invalid_argument);
  EXPECT_THROW(BoundaryReplicationPlacement r(table_, {.epsilon = 0.1, .max_replicas = 0}), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
