// The static protocol for any routing strategy (experiments/protocols/paper/static_strategies.h),
// on a six-frame sequence whose matches are worked out by hand.
#include <algorithm>
#include <cmath>
#include <optional>
#include <memory>

#include <gtest/gtest.h>

#include "agents/placement/decentralized_placement.h"
#include "agents/placement/probe_placement.h"
#include "experiments/domain/evaluation/windowed_neighbours.h"
#include "experiments/protocols/paper/static_strategies.h"

namespace dvpr {
namespace {

// Six frames, 1-D descriptors 4 14 18 6 22 26 at x = 0 100 200 0 300 400: frame 3 revisits
// frame 0's place (R = 2 with r = 5 m). Window 1. Two robots (frames 0-2, 3-5), centroids at
// 0 (robot 0) and 10 (robot 1): frame 0 routes to robot 0, its revisit (6) and the rest to
// robot 1. Distance ratios second/nearest centroid: 1.5 for frames 0 and 3, >= 1.625 else.
class StaticStrategiesTest : public ::testing::Test {
 protected:
  StaticStrategiesTest() {
    data_.descriptors.resize(6, 1);
    data_.descriptors << 4, 14, 18, 6, 22, 26;
    data_.trajectory.positions = Positions::Zero(6, 3);
    data_.trajectory.positions.col(0) << 0, 100, 200, 0, 300, 400;
    data_.trajectory.headings = Positions::Zero(6, 3);
    CentroidMatrix c(2, 1);
    c << 0, 10;
    table_ = std::make_shared<const CentroidTable>(CentroidTable::RoundRobin(c, 2));
  }
  Dataset data_;
  std::shared_ptr<const CentroidTable> table_;
};

TEST_F(StaticStrategiesTest, NearestOwnerRoutingMatchesThePaperEvaluation) {
  const PaperEvaluator evaluator(data_, {.radius_m = 5, .suppression_frames = 1}, 2, 1);
  EXPECT_EQ(evaluator.relevant(), 2);
  // Centralized, by hand: q0 -> 3 and q3 -> 0 (score 4, correct) rank first, the rest wrong
  // (q1 -> 3, q2 -> 4, q4 -> 2, q5 -> 2, scores 16 or 64):
  // recall 0.5, 1 at precision 1, 1; AUC counts from the second step: 0.5.
  EXPECT_NEAR(evaluator.centralized().auc, 0.5, 1e-9);  // precision/recall carry a 1e-12 guard
  const PaperRunResult paper = evaluator.Evaluate(*table_, false);
  const PaperRunResult general = EvaluatePlacement(evaluator, DecentralizedPlacement(table_), "decentralized", false);
  // Robot 0 stores only frame 0 (q0 has no candidate); q3 searches robot 1 and finds frame 1:
  // nothing correct, AUC 0. Searches: robot 0 one, robot 1 five: balance 5 / (6 / 2).
  EXPECT_EQ(general.row.auc, 0.0);
  EXPECT_EQ(paper.row.auc, general.row.auc);
  EXPECT_DOUBLE_EQ(general.row.worst_balance_ratio, 5.0 / 3.0);
  EXPECT_DOUBLE_EQ(paper.row.worst_balance_ratio, general.row.worst_balance_ratio);
  ASSERT_EQ(general.per_robot.size(), 2u);
  EXPECT_EQ(general.per_robot[1].queries_received, 5);
  EXPECT_EQ(general.per_robot[1].comparisons, paper.per_robot[1].comparisons);
}

TEST_F(StaticStrategiesTest, BoundaryReplicationRecoversTheRevisitAcrossTheBorder) {
  const PaperEvaluator evaluator(data_, {.radius_m = 5, .suppression_frames = 1}, 2, 1);
  // Only frames 0 (distances 4, 6) and 3 (6, 4) are within 1.55 x their nearest of both
  // centroids: stored at both robots, so q0 finds 3 and q3 finds 0, as centralized.
  const BoundaryReplicationPlacement r(table_, {.epsilon = 0.55, .max_replicas = 2});
  const PaperRunResult got = EvaluatePlacement(evaluator, r, "replicate", false);
  EXPECT_DOUBLE_EQ(got.row.relative_auc, 1.0);
  EXPECT_EQ(got.row.key.strategy, "replicate");
  // Searches unchanged (one robot each); stores: robot 0 keeps 0 and 3, robot 1 all six.
  EXPECT_DOUBLE_EQ(got.row.worst_balance_ratio, 5.0 / 3.0);
  EXPECT_EQ(got.per_robot[0].stored, 2);
  EXPECT_EQ(got.per_robot[1].stored, 6);
  // Comparisons: q0 vs {3}; robot 1: q1 {3,4,5}, q2 {0,4,5}, q3 {0,1,5}, q4 {0,1,2}, q5 {0,1,2,3}.
  EXPECT_EQ(got.per_robot[0].comparisons, 1);
  EXPECT_EQ(got.per_robot[1].comparisons, 16);
}

TEST_F(StaticStrategiesTest, TwoProbesSearchBothRobotsAndPayInBalance) {
  const PaperEvaluator evaluator(data_, {.radius_m = 5, .suppression_frames = 1}, 2, 1);
  const MultiProbePlacement r(table_, {.probes = 2, .epsilon = -1});
  const PaperRunResult got = EvaluatePlacement(evaluator, r, "multi_probe_2", false);
  EXPECT_DOUBLE_EQ(got.row.relative_auc, 1.0);
  EXPECT_DOUBLE_EQ(got.row.worst_balance_ratio, 6.0 / 3.0);  // every robot serves every query
}

TEST(WindowedNeighboursWhere, EqualsBruteForceForAnyListSize) {
  // 40 frames on a line with a few exact repeats; candidate relation: (i + j) % 3 != 0.
  DescriptorMatrix x(40, 2);
  for (int i = 0; i < 40; ++i) x.row(i) << static_cast<float>((i * 7) % 13), static_cast<float>(i % 5);
  const auto candidate = [](std::int64_t i, std::int64_t j) { return (i + j) % 3 != 0; };
  for (int list_size : {1, 4, 64}) {
    const WindowedNeighbours nn(x, 3, list_size, 1);
    const auto got = nn.BestMatchesWhere(candidate);
    for (int i = 0; i < 40; ++i) {
      std::optional<FrameId> want;
      double best = 0;
      for (int j = 0; j < 40; ++j) {
        if (std::abs(i - j) <= 3 || !candidate(i, j)) continue;
        const double d = (x.row(i).cast<double>() - x.row(j).cast<double>()).squaredNorm();
        if (!want || d < best) want = FrameId(j), best = d;
      }
      ASSERT_EQ(got[static_cast<std::size_t>(i)].match, want) << "list " << list_size << " query " << i;
      if (want) {
        EXPECT_EQ(got[static_cast<std::size_t>(i)].score, best);
      }
    }
  }
}

}  // namespace
}  // namespace dvpr
