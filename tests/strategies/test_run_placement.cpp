// BuildRunPlacement (experiments/domain/strategies/run_placement.h) on hand-made 1-D centroids, given as the
// run's centroid file so no k-means decides them: which robots search and store a hand-placed
// descriptor, worked out by hand from the strategy's rule.
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/domain/data/npy.h"
#include "experiments/domain/strategies/deployment_sample.h"
#include "experiments/domain/strategies/run_placement.h"
#include "tests/descriptor_support.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;
using testing_support::Column;
using testing_support::Robots;

// Writes centroids as run 0's file for `robots` robots and points the inputs at it.
// The run's family of the type a test expects; another family fails the test (the exception
// reaches GoogleTest).
template <class T>
const T& FamilyOf(const RunPlacement& r) {
  const T* f = r.As<T>();
  if (f == nullptr) throw std::runtime_error("the strategy is of another family");
  return *f;
}
const StatelessFamily& Stateless(const RunPlacement& r) { return FamilyOf<StatelessFamily>(r); }

class RunPlacementTest : public ::testing::Test {
 protected:
  RunPlacementTest() : dir_(dvpr::testing_support::FreshTestDir("strategies")) {
    inputs_.training = &training_;
    inputs_.deployment = &deployment_;
    inputs_.centroids.seed = 1;
    inputs_.centroids.centroids_pattern = (dir_ / "c_n{robots}_r{run}.npy").string();
  }
  void Centroids(int robots, const DescriptorMatrix& c) { WriteNpy(dir_ / ("c_n" + std::to_string(robots) + "_r0.npy"), c); }
  RunPlacement Build(const std::string& name, int robots) { return BuildRunPlacement(ParseStrategy(name), inputs_, robots, 0); }

  fs::path dir_;
  DescriptorMatrix training_ = Column({});
  DescriptorMatrix deployment_ = Column({0, 10, 20});
  StrategyInputs inputs_;
};

// Three robots, one centroid each: 0, 10, 20 owned by robots 0, 1, 2 (round robin).
class ThreeRobotsTest : public RunPlacementTest {
 protected:
  ThreeRobotsTest() { Centroids(3, Column({0, 10, 20})); }
};

TEST_F(ThreeRobotsTest, DecentralizedSendsToTheNearestCentroidsOwner) {
  const RunPlacement r = Build("decentralized", 3);
  ASSERT_NE(r.table(), nullptr);
  EXPECT_EQ(r.table()->num_centroids(), 3);
  EXPECT_EQ(Stateless(r).table.get(), r.table());
  EXPECT_EQ(r.As<ReclusterFamily>(), nullptr);
  EXPECT_EQ(Stateless(r).failover, nullptr);  // failover is off
  // 12: nearest 10 (distance 2), owned by robot 1, which searches and stores it.
  const float twelve = 12;
  const PlacementDecision d = Stateless(r).strategy->Route(RobotId(0), &twelve);
  EXPECT_EQ(d.search_at, Robots({1}));
  EXPECT_EQ(d.store_at, Robots({1}));
  // 16: nearest 20 (4 < 6): robot 2.
  const float sixteen = 16;
  EXPECT_EQ(Stateless(r).strategy->Route(RobotId(0), &sixteen).search_at, Robots({2}));
}

TEST_F(ThreeRobotsTest, BroadcastSearchesEverywhereAndHasNoTable) {
  const RunPlacement r = Build("broadcast", 3);
  EXPECT_EQ(r.table(), nullptr);
  EXPECT_EQ(Stateless(r).team->num_robots(), 3);
  const float twelve = 12;
  const PlacementDecision d = Stateless(r).strategy->Route(RobotId(1), &twelve);
  EXPECT_EQ(d.search_at, Robots({0, 1, 2}));
  EXPECT_EQ(d.store_at, Robots({1}));  // the querying robot keeps its own frame
}

TEST_F(ThreeRobotsTest, MultiProbeTwoSearchesTheTwoNearestOwnersAndStoresAtTheNearest) {
  const RunPlacement r = Build("multi_probe_2", 3);
  // 12: 10 (2), 20 (8), 0 (12): robots 1 and 2 search, robot 1 stores.
  const float twelve = 12;
  const PlacementDecision d = Stateless(r).strategy->Route(RobotId(0), &twelve);
  EXPECT_EQ(d.search_at, Robots({1, 2}));
  EXPECT_EQ(d.store_at, Robots({1}));
  // 4: 0 (4), 10 (6), 20 (16): robots 0 and 1.
  const float four = 4;
  EXPECT_EQ(Stateless(r).strategy->Route(RobotId(2), &four).search_at, Robots({0, 1}));
}

TEST_F(ThreeRobotsTest, ReplicateStoresAtOwnersWithinOnePlusEpsilonOfTheNearest) {
  const RunPlacement r = Build("replicate_0.5", 3);
  // 14.5: 10 at 4.5, 20 at 5.5 <= 1.5 x 4.5 = 6.75, 0 at 14.5 > 6.75: stored at robots 1 and 2,
  // searched at the nearest only.
  const float x = 14.5f;
  const PlacementDecision d = Stateless(r).strategy->Route(RobotId(0), &x);
  EXPECT_EQ(d.search_at, Robots({1}));
  EXPECT_EQ(d.store_at, Robots({1, 2}));
  // 12: 10 at 2, 20 at 8 > 3: robot 1 only.
  const float twelve = 12;
  EXPECT_EQ(Stateless(r).strategy->Route(RobotId(0), &twelve).store_at, Robots({1}));
  // replicate_3_r2: every centroid is within 4 x 4.5 = 18 of 14.5, but at most 2 are taken.
  EXPECT_EQ(Stateless(Build("replicate_3_r2", 3)).strategy->Route(RobotId(0), &x).store_at, Robots({1, 2}));
}

// With failover on, a stateless strategy's team is the FailoverTeam around the strategy, which
// still routes as without it while every robot is alive; re-clustering has no failover.
TEST_F(ThreeRobotsTest, FailoverWrapsTheStatelessStrategyAndRefusesReclustering) {
  inputs_.failover.enabled = true;
  const RunPlacement r = Build("decentralized", 3);
  const StatelessFamily& f = Stateless(r);
  ASSERT_NE(f.failover, nullptr);
  EXPECT_EQ(static_cast<const TeamPlacement*>(f.failover), f.team.get());
  EXPECT_NE(static_cast<const TeamPlacement*>(f.strategy), f.team.get());
  const float twelve = 12;
  EXPECT_EQ(f.strategy->Route(RobotId(0), &twelve).search_at, Robots({1}));
  EXPECT_THROW(Build("recluster_c1_p50", 3), std::invalid_argument);
}

TEST_F(ThreeRobotsTest, StrategiesOfOneRunShareTheCachedCentroids) {
  RunCentroidCache cache;
  inputs_.cache = &cache;
  const RunPlacement a = Build("decentralized", 3);
  fs::remove_all(dir_);  // a second read of the file would now fail
  const RunPlacement b = Build("multi_probe_2", 3);
  EXPECT_EQ(b.table()->centroids(), a.table()->centroids());
  inputs_.cache = nullptr;
  EXPECT_THROW(Build("decentralized", 3), std::exception);
}

// Two robots, two clusters each: centroids 0, 10, 20, 30 (round robin: robots 0 1 0 1).
class LptTest : public RunPlacementTest {
 protected:
  LptTest() { Centroids(2, Column({0, 10, 20, 30})); }
};

TEST_F(LptTest, LptPacksTheClustersOnTheDeploymentSamplesLoads) {
  // 41 frames; the sample (frames 0, 20, 40) is 29, 29, 1: counts 1 0 0 2, plus one each: loads
  // 2 1 1 3. LPT, heaviest first: 30 -> robot 0 (3), 0 -> robot 1 (2), 10 -> robot 1 (3), then
  // 20 to the lower id of two robots at 3: robot 0. So 1 goes to robot 1 (round robin: 0).
  deployment_ = DescriptorMatrix::Constant(41, 1, 15.0f);
  deployment_(0, 0) = deployment_(20, 0) = 29;
  deployment_(40, 0) = 1;
  const RunPlacement r = Build("lpt_c2", 2);
  ASSERT_EQ(r.table()->num_centroids(), 4);
  const float one = 1, nineteen = 19, twenty_nine = 29;
  EXPECT_EQ(r.table()->RouteOf(&one), RobotId(1));
  EXPECT_EQ(r.table()->RouteOf(&nineteen), RobotId(0));
  EXPECT_EQ(r.table()->RouteOf(&twenty_nine), RobotId(0));
  EXPECT_EQ(Stateless(r).strategy->Route(RobotId(0), &one).search_at, Robots({1}));
}

TEST_F(LptTest, LptTrainTakesTheLoadsFromTheTrainingSet) {
  // Training 1 1 1 29: counts 3 0 0 1, loads 4 1 1 2. LPT: 0 -> robot 0 (4), 30 -> robot 1 (2),
  // 10 -> robot 1 (3), 20 -> the less loaded robot 1 (3 < 4). So 19 goes to robot 1 (round
  // robin: 0).
  training_ = Column({1, 1, 1, 29});
  const RunPlacement r = Build("lpt_c2_train", 2);
  const float one = 1, nineteen = 19;
  EXPECT_EQ(r.table()->RouteOf(&one), RobotId(0));
  EXPECT_EQ(r.table()->RouteOf(&nineteen), RobotId(1));
}

TEST_F(LptTest, ReclusteringStartsFromItsTableAndCarriesItsParameters) {
  // recluster_c2_p50: C = 2 (the four centroids), period 50, seeded RunSeed(1, 2, 0).
  training_ = Column({1, 1, 1, 29});
  deployment_ = DescriptorMatrix::Constant(200, 1, 5.0f);
  const RunPlacement r = Build("recluster_c2_p50", 2);
  const ReclusterFamily& f = FamilyOf<ReclusterFamily>(r);
  EXPECT_EQ(f.params.clusters_per_robot, 2);
  EXPECT_EQ(f.params.period, 50);
  EXPECT_EQ(f.params.seed, RunSeed(1, 2, 0));
  ASSERT_NE(r.table(), nullptr);
  EXPECT_EQ(f.table.get(), r.table());
  const float nineteen = 19;
  EXPECT_EQ(r.table()->RouteOf(&nineteen), RobotId(1));  // lpt_c2_train's table, as above
  EXPECT_EQ(f.team->num_robots(), 2);
}

TEST_F(RunPlacementTest, CentroidFilesMustHaveKRows) {
  Centroids(2, Column({0, 10, 20}));  // 3 rows, lpt_c2 needs 4
  EXPECT_THROW(Build("lpt_c2", 2), std::invalid_argument);
}

TEST(RunPlacement, NeedsTheTrainingAndDeploymentDescriptors) {
  EXPECT_THROW(BuildRunPlacement(ParseStrategy("broadcast"), StrategyInputs{}, 2, 0), std::invalid_argument);
}

// Tables that cluster for themselves (k-means on hand-made data, no file).
StrategyInputs Inputs(const DescriptorMatrix& training, const DescriptorMatrix& deployment) {
  StrategyInputs in;
  in.training = &training;
  in.deployment = &deployment;
  return in;
}

TEST(SampleTables, ClusterWhereTheDeploymentIs) {
  // Deployment: 20 frames at 0, then 20 at 100; the sample (frames 0 and 20) is {0, 100}, so
  // k-means (k = min(2 x 2, 2 sample rows)) puts one centroid on each and LPT gives one per robot,
  // whatever the training set says.
  DescriptorMatrix deployment(40, 1);
  for (int i = 0; i < 40; ++i) deployment(i, 0) = i < 20 ? 0.0f : 100.0f;
  const DescriptorMatrix training = DescriptorMatrix::Constant(10, 1, 50.0f);
  const StrategyInputs in = Inputs(training, deployment);
  const RunPlacement routing = BuildRunPlacement(ParseStrategy("sample_c2"), in, 2, 0);
  const CentroidTable* table = routing.table();
  EXPECT_EQ(table->num_centroids(), 2);
  const float a = 1, b = 99;
  EXPECT_NE(table->RouteOf(&a), table->RouteOf(&b));
}

// The lopsided set of tests/agents/test_balanced_kmeans.cpp: plain k-means (k = 2) puts the
// outlier 100 alone (centroids 4.8 and 100), balanced k-means splits 3 + 3 (centroids 1 and
// 40.33). A query at 30 is nearest 4.8 in the first table (25.2 < 70) but 40.33 in the second
// (10.33 < 29): it then goes to the robot that owns 100's cluster, not 1's.
DescriptorMatrix Lopsided() { return Column({0, 1, 2, 10, 11, 100}); }

TEST(BalancedTables, SplitTheTrainingSetIntoEqualClusters) {
  const DescriptorMatrix training = Lopsided();
  const DescriptorMatrix deployment = DescriptorMatrix::Constant(10, 1, 50.0f);
  const StrategyInputs in = Inputs(training, deployment);
  const RunPlacement balanced_routing = BuildRunPlacement(ParseStrategy("balanced_c1"), in, 2, 0);
  const CentroidTable* balanced = balanced_routing.table();
  ASSERT_EQ(balanced->num_centroids(), 2);
  const float one = 1, thirty = 30, hundred = 100;
  EXPECT_NE(balanced->RouteOf(&thirty), balanced->RouteOf(&one));
  EXPECT_EQ(balanced->RouteOf(&thirty), balanced->RouteOf(&hundred));
  // The paper's table on the same training set sends 30 with 1.
  const RunPlacement paper_routing = BuildRunPlacement(ParseStrategy("replicate_0.1"), in, 2, 0);
  const CentroidTable* paper = paper_routing.table();
  EXPECT_EQ(paper->RouteOf(&thirty), paper->RouteOf(&one));
  EXPECT_NE(paper->RouteOf(&thirty), paper->RouteOf(&hundred));
}

TEST(BalancedTables, BalancedSampleSplitsTheDeploymentSample) {
  // 101 deployment frames whose every 20th frame is the lopsided set; the training set is
  // irrelevant. balanced_sample_c1 clusters the sample into 3 + 3 as above.
  DescriptorMatrix deployment = DescriptorMatrix::Constant(101, 1, 50.0f);
  const DescriptorMatrix lopsided = Lopsided();
  for (int i = 0; i < 6; ++i) deployment(i * 20, 0) = lopsided(i, 0);
  const DescriptorMatrix training = DescriptorMatrix::Constant(10, 1, -7.0f);
  const StrategyInputs in = Inputs(training, deployment);
  const RunPlacement r = BuildRunPlacement(ParseStrategy("balanced_sample_c1+replicate_0.5_r5"), in, 2, 0);
  ASSERT_EQ(r.table()->num_centroids(), 2);
  const float one = 1, thirty = 30, hundred = 100;
  EXPECT_NE(r.table()->RouteOf(&thirty), r.table()->RouteOf(&one));
  EXPECT_EQ(r.table()->RouteOf(&thirty), r.table()->RouteOf(&hundred));
  // Replication within 1.5 x the nearest distance: 30 is 10.33 from 40.33 and 29 from 1
  // (29 > 15.5): stored at one robot; 20 is 19 from 1 and 20.33 from 40.33 (<= 28.5): at both.
  EXPECT_EQ(Stateless(r).strategy->Route(RobotId(0), &thirty).store_at.size(), 1U);
  const float twenty = 20;
  EXPECT_EQ(Stateless(r).strategy->Route(RobotId(0), &twenty).store_at.size(), 2U);
  EXPECT_EQ(Stateless(r).strategy->Route(RobotId(0), &twenty).search_at.size(), 1U);
}

TEST(DeploymentSample, TakesEveryTwentiethFrame) {
  DescriptorMatrix x(41, 1);
  for (int i = 0; i < 41; ++i) x(i, 0) = static_cast<float>(i);
  const DescriptorMatrix s = DeploymentSample(x);
  ASSERT_EQ(s.rows(), 3);
  EXPECT_EQ(s(0, 0), 0.0f);
  EXPECT_EQ(s(1, 0), 20.0f);
  EXPECT_EQ(s(2, 0), 40.0f);
}

// bow_ strategies take their word owners from the dataset's BoW vectors, no table. Document
// frequencies of {0, 1}, {0}, {2}: [2, 1, 1]; LPT on 2 robots: w0 -> r0, w1 -> r1, w2 -> r1.
TEST_F(RunPlacementTest, BagOfWordsStrategiesAssignWords) {
  BowData bow;
  bow.vocabulary = 3;
  bow.frames = {{{0, .5f}, {1, .5f}}, {{0, 1.f}}, {{2, 1.f}}};
  inputs_.bow = &bow;
  const RunPlacement modulo = Build("bow_decentralized", 2);
  const auto& words = FamilyOf<BowFamily>(modulo).words;
  ASSERT_TRUE(words);
  EXPECT_EQ(words->OwnerOf(2), RobotId(0));
  EXPECT_FALSE(modulo.table());
  const RunPlacement df = Build("bow_decentralized_df", 2);
  const auto& df_words = FamilyOf<BowFamily>(df).words;
  ASSERT_TRUE(df_words);
  EXPECT_EQ(df_words->OwnerOf(0), RobotId(0));
  EXPECT_EQ(df_words->OwnerOf(1), RobotId(1));
  EXPECT_EQ(df_words->OwnerOf(2), RobotId(1));
  EXPECT_FALSE(FamilyOf<BowFamily>(Build("bow_broadcast", 2)).words);
  inputs_.bow = nullptr;
  EXPECT_THROW(Build("bow_decentralized", 2), std::invalid_argument);
}

// What a team of BoW agents sends by (BowTeamPlan): the distributed index its word owners,
// broadcast none (the whole vector to every robot), centralized one server, robot 0, owning
// every word of the vocabulary.
TEST_F(RunPlacementTest, BagOfWordsStrategiesGiveTheirTeamPlan) {
  BowData bow;
  bow.vocabulary = 3;
  bow.frames = {{{0, .5f}, {1, .5f}}, {{0, 1.f}}, {{2, 1.f}}};
  inputs_.bow = &bow;
  const RunPlacement modulo = Build("bow_decentralized", 3);
  const BowTeamPlan& plan = FamilyOf<BowFamily>(modulo).team;
  EXPECT_EQ(plan.robots, 3);
  ASSERT_TRUE(plan.words);
  EXPECT_EQ(plan.words->OwnerOf(2), RobotId(2));
  EXPECT_EQ(plan.words, FamilyOf<BowFamily>(modulo).words);  // the distributed index itself
  EXPECT_TRUE(FamilyOf<BowFamily>(Build("bow_broadcast", 3)).team.broadcast());
  const RunPlacement central = Build("bow_centralized", 3);
  const BowFamily& c = FamilyOf<BowFamily>(central);
  EXPECT_FALSE(c.words);  // the static protocol's reference keeps its own index
  ASSERT_TRUE(c.team.words);
  for (const int w : {0, 1, 2}) EXPECT_EQ(c.team.words->OwnerOf(w), RobotId(0)) << w;
  EXPECT_EQ(Build("broadcast", 3).As<BowFamily>(), nullptr);
}

}  // namespace
}  // namespace dvpr
