// Adaptive re-clustering in the static protocol (experiments/protocols/paper/static_recluster.h): the max(e_i, e_j)
// candidates rule, balance, where frames end up and the re-clustering bytes, on a six-frame
// sequence with hand-made tables; the planner's own k-means tables on a 1-D toy.
#include <algorithm>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "agents/placement/decentralized_placement.h"
#include "experiments/protocols/paper/static_recluster.h"
#include "experiments/protocols/paper/static_strategies.h"

namespace dvpr {
namespace {

std::shared_ptr<const CentroidTable> Table(std::initializer_list<float> centroids, std::initializer_list<int> owners) {
  CentroidMatrix c(static_cast<Eigen::Index>(centroids.size()), 1);
  Eigen::Index i = 0;
  for (float v : centroids) c(i++, 0) = v;
  std::vector<RobotId> o;
  for (int r : owners) o.push_back(RobotId(r));
  return std::make_shared<const CentroidTable>(c, o, 2);
}

// Six frames, 1-D descriptors 4 14 18 22 6 26 at x = 0 100 200 300 0 400: frame 4 revisits
// frame 0's place (R = 2 with r = 5 m). Window 1. Robots: frames 0-2 (steps 0 1 2) and 3-5 (steps
// 0 1 2); period 1, so a frame's epoch is its step: frames 0, 3 in epoch 0; 1, 4 in 1; 2, 5 in 2.
// Tables, and where they route the six frames:
//   T0: centroids 0 (robot 0), 10 (robot 1):  r0 r1 r1 r1 r1 r1
//   T1: centroids 5 (robot 0), 20 (robot 1):  r0 r1 r1 r1 r0 r1
//   T2: centroids 5 (robot 1), 20 (robot 0):  r1 r0 r0 r0 r1 r0
class StaticReclusterTest : public ::testing::Test {
 protected:
  StaticReclusterTest() {
    data_.descriptors.resize(6, 1);
    data_.descriptors << 4, 14, 18, 22, 6, 26;
    data_.trajectory.positions = Positions::Zero(6, 3);
    data_.trajectory.positions.col(0) << 0, 100, 200, 300, 0, 400;
    data_.trajectory.headings = Positions::Zero(6, 3);
    params_.period = 1;
    tables_ = {Table({0, 10}, {0, 1}), Table({5, 20}, {0, 1}), Table({5, 20}, {1, 0})};
  }
  StaticReclusterPlan Plan() const { return MakeStaticReclusterPlan(data_.descriptors, 2, tables_, params_); }
  Dataset data_;
  ReclusterParams params_;
  std::vector<std::shared_ptr<const CentroidTable>> tables_;
};

TEST_F(StaticReclusterTest, CandidatesShareAnOwnerUnderTheLaterFramesTable) {
  const StaticReclusterPlan plan = Plan();
  ASSERT_EQ(plan.epochs(), 2);
  EXPECT_EQ(plan.epoch, (std::vector<int>{0, 1, 2, 0, 1, 2}));
  // (0, 4): epoch max(0, 1) = 1, T1 puts both at robot 0: the revisit is found although T0 split
  // them. (0, 3): both epoch 0, T0 has them apart (T1 and T2 do not matter: frame 3 was searched
  // at robot 1 while frame 0 sat at robot 0).
  EXPECT_TRUE(plan.Candidates(0, 4));
  EXPECT_TRUE(plan.Candidates(4, 0));
  EXPECT_FALSE(plan.Candidates(0, 3));
  EXPECT_TRUE(plan.Candidates(1, 3));   // T1: r1, r1
  EXPECT_FALSE(plan.Candidates(1, 4));  // T1: r1, r0
  EXPECT_FALSE(plan.Candidates(0, 2));  // T2: r1, r0
  EXPECT_TRUE(plan.Candidates(1, 5));   // T2: r0, r0
  EXPECT_TRUE(plan.Candidates(3, 5));   // T2: r0, r0
  EXPECT_EQ(plan.SearchedAt(4), RobotId(0));  // T1
  EXPECT_EQ(plan.SearchedAt(2), RobotId(0));  // T2
  EXPECT_EQ(plan.FinalOwner(0), RobotId(1));
}

TEST_F(StaticReclusterTest, RunFindsTheRevisitTheFixedTableMisses) {
  const PaperEvaluator evaluator(data_, {.radius_m = 5, .suppression_frames = 1}, 2, 1);
  // Candidates (|i - j| > 1, max-epoch rule): q0 {4}, q1 {3, 5}, q2 {5}, q3 {1, 5}, q4 {0},
  // q5 {1, 2, 3}. Best: q0 -> 4 (score 4, correct), q4 -> 0 (4, correct), q1 -> 3 (64), q2 -> 5
  // (64), q3 -> 5 (16), q5 -> 3 (16), all wrong. Ranked: q0, q4 (recall 0.5, 1 at precision 1),
  // then wrong ones: AUC = (1 - 0.5) x 1 = 0.5, the centralized AUC (test_static_strategies).
  const PaperRunResult got = EvaluateRecluster(evaluator, Plan(), "recluster", false);
  EXPECT_NEAR(got.row.auc, 0.5, 1e-9);
  EXPECT_NEAR(got.row.relative_auc, 1.0, 1e-9);
  // T0 alone (the paper's rule): frame 0 is alone at robot 0 and q4 finds frame 1: AUC 0.
  const PaperRunResult fixed = EvaluatePlacement(evaluator, DecentralizedPlacement(tables_[0]), "t0", false);
  EXPECT_EQ(fixed.row.auc, 0.0);
  // Searched at (table of the own epoch): q0 T0 r0, q3 T0 r1, q1 T1 r1, q4 T1 r0, q2 T2 r0,
  // q5 T2 r0: robot 0 serves 4, robot 1 2; balance 4 / (6 / 2).
  EXPECT_DOUBLE_EQ(got.row.worst_balance_ratio, 4.0 / 3.0);
  ASSERT_EQ(got.per_robot.size(), 2u);
  EXPECT_EQ(got.per_robot[0].queries_received, 4);
  EXPECT_EQ(got.per_robot[1].queries_received, 2);
  // Stored at the end (T2): robot 0 frames 1 2 3 5, robot 1 frames 0 4.
  EXPECT_EQ(got.per_robot[0].stored, 4);
  EXPECT_EQ(got.per_robot[1].stored, 2);
  // Comparisons = candidates of the queries served: robot 0 q0 1 + q4 1 + q2 1 + q5 3 = 6;
  // robot 1 q3 2 + q1 2 = 4.
  EXPECT_EQ(got.per_robot[0].comparisons, 6);
  EXPECT_EQ(got.per_robot[1].comparisons, 4);
  EXPECT_EQ(got.row.key.strategy, "recluster");
  EXPECT_EQ(got.row.queries, 6);
}

TEST_F(StaticReclusterTest, TrafficCountsSamplesTablesAndMigrationsInEncodedBytes) {
  // Stride 4: the sample of epochs 1 and 2 is the step-0 frames 0 and 3. At boundary 1 they sit
  // under T0 at robots 0 and 1; at boundary 2 under T1 at robots 0 and 1. Robot 1 (not the leader)
  // uploads one descriptor each time: 28 + 1 x (6 + 4) = 38 bytes, twice.
  // Tables: k = 2, dim 1: 26 + 2 x (4 + 2) = 38 bytes, to the one other robot, twice.
  // Migrations T0 -> T1 (frames 0 and 3): none move. T1 -> T2 (frames 0, 3, 1, 4): 0 and 4 go
  // 0 -> 1, 3 and 1 go 1 -> 0: two batches of two, 28 + 2 x 10 = 48 bytes each.
  const ReclusterTraffic t = CountReclusterTraffic(Plan(), 1);
  EXPECT_EQ(t.sample_messages, 2);
  EXPECT_EQ(t.sample_bytes, 76);
  EXPECT_EQ(t.table_messages, 2);
  EXPECT_EQ(t.table_bytes, 76);
  EXPECT_EQ(t.migration_messages, 2);
  EXPECT_EQ(t.migration_bytes, 96);
  EXPECT_EQ(t.migrated, 4);
  const PaperEvaluator evaluator(data_, {.radius_m = 5, .suppression_frames = 1}, 2, 1);
  const PaperRunResult got = EvaluateRecluster(evaluator, Plan(), "recluster", false);
  EXPECT_EQ(got.row.messages, 6);
  EXPECT_EQ(got.row.payload_bytes, 248);
  EXPECT_EQ(got.row.wire_bytes, 0);  // no network in the static protocol
}

TEST_F(StaticReclusterTest, WrongNumberOfTablesIsRejected) {
  tables_.pop_back();
  EXPECT_THROW(Plan(), std::invalid_argument);
}

TEST(StaticReclusterSample, EveryFourthStepOfEachStreamBeforeTheBoundary) {
  // 20 frames, 2 robots (frames 0-9 and 10-19), period 5: epoch 1's sample is steps 0 and 4 of
  // each stream: frames 0, 4, 10, 14.
  std::vector<int> step;
  for (int f = 0; f < 20; ++f) step.push_back(f % 10);
  ReclusterParams p;
  p.period = 5;
  EXPECT_EQ(ReclusterSampleFrames(step, 1, p), (std::vector<int>{0, 4, 10, 14}));
}

// The 1-D toy of test_sim_recluster: 2 robots x 8 frames, period 4, sample stride 2, one cluster
// per robot. Values near 0 and near 100; the initial table sends near-0 to robot 1.
TEST(StaticReclusterPlanner, ClustersTheSampleSeenBeforeTheBoundary) {
  DescriptorMatrix x(16, 1);
  x.col(0) << 0, 1, 0, 99, 2, 98, 3, 97,  // robot 0
      0, 1, 100, 101, 2, 99, 3, 102;      // robot 1
  ReclusterParams p;
  p.clusters_per_robot = 1;
  p.period = 4;
  p.sample_stride = 2;
  const StaticReclusterPlan plan = PlanStaticRecluster(x, Table({0, 100}, {1, 0}), p);
  // One re-clustering ((8 - 1) / 4 = 1). Its sample: steps 0 and 2 of each stream = frames 0, 2,
  // 8, 10 = values 0 0 0 100: centroids 0 and 100, loads 4 and 2: 0 -> robot 0, 100 -> robot 1.
  ASSERT_EQ(plan.epochs(), 1);
  const float near0 = 5, near100 = 95;
  EXPECT_EQ(plan.tables[1]->RouteOf(&near0), RobotId(0));
  EXPECT_EQ(plan.tables[1]->RouteOf(&near100), RobotId(1));
  // Traffic: robot 1 holds frames 0, 2, 8 of the sample under T0 (near 0): 28 + 3 x 10 = 58.
  // Table: 38. Migrations of frames 0-3 and 8-11: near-0 frames 0 1 2 8 9 go 1 -> 0
  // (28 + 5 x 10 = 78), near-100 frames 3 10 11 go 0 -> 1 (28 + 3 x 10 = 58).
  const ReclusterTraffic t = CountReclusterTraffic(plan, 1);
  EXPECT_EQ(t.sample_bytes, 58);
  EXPECT_EQ(t.table_bytes, 38);
  EXPECT_EQ(t.migration_messages, 2);
  EXPECT_EQ(t.migration_bytes, 136);
  EXPECT_EQ(t.migrated, 8);
}

}  // namespace
}  // namespace dvpr
