// The static protocol for any routing strategy (experiments/protocols/paper/static_strategies.h) and the
// strategy catalogue, on a six-frame sequence whose matches are worked out by hand.
#include <algorithm>
#include <cmath>
#include <optional>
#include <memory>

#include <gtest/gtest.h>

#include "agents/decentralized_routing.h"
#include "agents/probe_routing.h"
#include "experiments/config/config.h"
#include "experiments/protocols/paper/static_strategies.h"
#include "experiments/strategies/strategy_catalogue.h"
#include "experiments/evaluation/windowed_neighbours.h"

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
  const PaperRunResult general = EvaluateRouting(evaluator, DecentralizedRouting(table_), "decentralized", false);
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
  const BoundaryReplicationRouting r(table_, {.epsilon = 0.55, .max_replicas = 2});
  const PaperRunResult got = EvaluateRouting(evaluator, r, "replicate", false);
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
  const MultiProbeRouting r(table_, {.probes = 2, .epsilon = -1});
  const PaperRunResult got = EvaluateRouting(evaluator, r, "multi_probe_2", false);
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

TEST(StrategyCatalogue, NamesAreKnownToConfigsAndCarryTheirParameters) {
  const StrategySpec* s = FindStrategySpec("lpt_c10+adaptive_probe_0.1");
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->table, StrategySpec::Table::kLpt);
  EXPECT_EQ(s->clusters_per_robot, 10);
  EXPECT_EQ(s->routing, StrategySpec::Routing::kProbe);
  EXPECT_EQ(s->probe.epsilon, 0.1);
  const StrategySpec* b = FindStrategySpec("bounded_c10_0.25");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->balance.epsilon, 0.25);
  EXPECT_EQ(FindStrategySpec("lpt_c7"), nullptr);
  const auto& known = KnownStrategies();
  for (const std::string& name : BeyondPaperStrategyNames()) {
    EXPECT_NE(std::find(known.begin(), known.end(), name), known.end()) << name;
  }
}

TEST(StrategyCatalogue, SampleTablesClusterWhereTheDeploymentIs) {
  // Deployment: 20 frames at 0, then 20 at 100; the sample (frames 0 and 20) is {0, 100}, so
  // k-means (k = min(2 x 2, 2 sample rows)) puts one centroid on each and LPT gives one per robot,
  // whatever the training set says.
  DescriptorMatrix deployment(40, 1);
  for (int i = 0; i < 40; ++i) deployment(i, 0) = i < 20 ? 0.0f : 100.0f;
  const DescriptorMatrix training = DescriptorMatrix::Constant(10, 1, 50.0f);
  const StrategySpec* spec = FindStrategySpec("sample_c2");
  ASSERT_NE(spec, nullptr);
  const auto table = BuildStrategyTable(*spec, training, deployment, PaperProtocolParams{}, 2, 0);
  EXPECT_EQ(table->num_centroids(), 2);
  const float a = 1, b = 99;
  EXPECT_NE(table->RouteOf(&a), table->RouteOf(&b));
}

// The lopsided set of tests/agents/test_balanced_kmeans.cpp: plain k-means (k = 2) puts the
// outlier 100 alone (centroids 4.8 and 100), balanced k-means splits 3 + 3 (centroids 1 and
// 40.33). A query at 30 is nearest 4.8 in the first table (25.2 < 70) but 40.33 in the second
// (10.33 < 29): it then goes to the robot that owns 100's cluster, not 1's.
DescriptorMatrix Lopsided() {
  DescriptorMatrix x(6, 1);
  x << 0, 1, 2, 10, 11, 100;
  return x;
}

TEST(StrategyCatalogue, BalancedTablesSplitTheTrainingSetIntoEqualClusters) {
  const StrategySpec* spec = FindStrategySpec("balanced_c1");
  ASSERT_NE(spec, nullptr);
  EXPECT_EQ(spec->table, StrategySpec::Table::kBalanced);
  const DescriptorMatrix training = Lopsided();
  const DescriptorMatrix deployment = DescriptorMatrix::Constant(10, 1, 50.0f);
  const auto balanced = BuildStrategyTable(*spec, training, deployment, PaperProtocolParams{}, 2, 0);
  ASSERT_EQ(balanced->num_centroids(), 2);
  const float one = 1, thirty = 30, hundred = 100;
  EXPECT_NE(balanced->RouteOf(&thirty), balanced->RouteOf(&one));
  EXPECT_EQ(balanced->RouteOf(&thirty), balanced->RouteOf(&hundred));
  // The paper's table on the same training set sends 30 with 1.
  const auto paper = BuildStrategyTable(*FindStrategySpec("replicate_0.1"), training, deployment, PaperProtocolParams{}, 2, 0);
  EXPECT_EQ(paper->RouteOf(&thirty), paper->RouteOf(&one));
  EXPECT_NE(paper->RouteOf(&thirty), paper->RouteOf(&hundred));
}

TEST(StrategyCatalogue, BalancedSampleTablesSplitTheDeploymentSample) {
  // 101 deployment frames whose every 20th frame is the lopsided set; the training set is
  // irrelevant. balanced_sample_c1 clusters the sample into 3 + 3 as above; sample_c2 is not
  // comparable (k = 4), so the paper-like contrast is plain k-means on the same sample.
  DescriptorMatrix deployment = DescriptorMatrix::Constant(101, 1, 50.0f);
  const DescriptorMatrix lopsided = Lopsided();
  for (int i = 0; i < 6; ++i) deployment(i * 20, 0) = lopsided(i, 0);
  const DescriptorMatrix training = DescriptorMatrix::Constant(10, 1, -7.0f);
  const StrategySpec* spec = FindStrategySpec("balanced_sample_c1+replicate_0.5_r5");
  ASSERT_NE(spec, nullptr);
  EXPECT_EQ(spec->table, StrategySpec::Table::kBalancedSample);
  EXPECT_EQ(spec->routing, StrategySpec::Routing::kReplicate);
  const auto table = BuildStrategyTable(*spec, training, deployment, PaperProtocolParams{}, 2, 0);
  ASSERT_EQ(table->num_centroids(), 2);
  const float one = 1, thirty = 30, hundred = 100;
  EXPECT_NE(table->RouteOf(&thirty), table->RouteOf(&one));
  EXPECT_EQ(table->RouteOf(&thirty), table->RouteOf(&hundred));
  // Replication within 1.5 x the nearest distance: 30 is 10.33 from 40.33 and 29 from 1
  // (29 > 15.5): stored at one robot; 20 is 19 from 1 and 20.33 from 40.33 (<= 28.5): at both.
  const auto routing = MakeSpecRouting(*spec, table);
  EXPECT_EQ(routing->Route(RobotId(0), &thirty).store_at.size(), 1U);
  const float twenty = 20;
  EXPECT_EQ(routing->Route(RobotId(0), &twenty).store_at.size(), 2U);
  EXPECT_EQ(routing->Route(RobotId(0), &twenty).search_at.size(), 1U);
}

TEST(StrategyCatalogue, DeploymentSampleTakesEveryTwentiethFrame) {
  DescriptorMatrix x(41, 1);
  for (int i = 0; i < 41; ++i) x(i, 0) = static_cast<float>(i);
  const DescriptorMatrix s = DeploymentSample(x);
  ASSERT_EQ(s.rows(), 3);
  EXPECT_EQ(s(0, 0), 0.0f);
  EXPECT_EQ(s(1, 0), 20.0f);
  EXPECT_EQ(s(2, 0), 40.0f);
}

}  // namespace
}  // namespace dvpr
