// The progress on stderr (run_progress.h): the estimate weighs each run by its modelled cost
// (issue 48: a sweep whose larger teams run last was estimated at 12 s of its 93 s from its
// first, small runs), worked by hand, with a clock the test sets and a file in place of stderr.
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/sweep/run_progress.h"
#include "experiments/sweep/sweep_size.h"

namespace dvpr {
namespace {

using std::chrono::steady_clock;

// Three runs costing 1, 2 and 3 (6 in all). The first (1) done after 2 s: 2 s a unit, 5 units
// left, 10 s. Before, 2 s a run x 2 runs left = 4 s.
TEST(RemainingTimeTest, TheRunsLeftAreWeighedByTheirCost) {
  RemainingTime left({1, 2, 3});
  left.Finish(0);
  EXPECT_EQ(left.done(), 1U);
  EXPECT_DOUBLE_EQ(left.Estimate(2.0), 10.0);
}

// Runs finish out of order on parallel workers: the third (3) alone done after 6 s leaves 1 + 2
// = 3 units at 2 s each, 6 s; then the first (1) too after 8 s: 4 units in 8 s, 2 left, 4 s.
// Finishing a run twice counts it once.
TEST(RemainingTimeTest, WhichRunsAreDoneCountsNotHowMany) {
  RemainingTime left({1, 2, 3});
  left.Finish(2);
  EXPECT_DOUBLE_EQ(left.Estimate(6.0), 6.0);
  left.Finish(0);
  left.Finish(0);
  EXPECT_EQ(left.done(), 2U);
  EXPECT_DOUBLE_EQ(left.Estimate(8.0), 4.0);
  left.Finish(1);
  EXPECT_DOUBLE_EQ(left.Estimate(9.0), 0.0);
}

// Equal costs give the estimate as it was: 3 s for 1 of 4 runs, 3 left, 9 s. Runs that cost
// nothing by the model are counted instead: 1 of 3 free runs in 5 s, 2 left, 10 s. Nothing done:
// no estimate yet (0).
TEST(RemainingTimeTest, EqualOrZeroCostsCountTheRuns) {
  RemainingTime equal({1, 1, 1, 1});
  EXPECT_DOUBLE_EQ(equal.Estimate(3.0), 0.0);
  equal.Finish(1);
  EXPECT_DOUBLE_EQ(equal.Estimate(3.0), 9.0);
  RemainingTime costless({0, 0, 0});
  costless.Finish(0);
  EXPECT_DOUBLE_EQ(costless.Estimate(5.0), 10.0);
  EXPECT_THROW((RemainingTime(std::vector<double>{1, -1})), std::invalid_argument);
  EXPECT_THROW(costless.Finish(3), std::out_of_range);
}

// What a file (not a terminal) receives: the first run's line, then one a decile.
class ProgressOutputTest : public ::testing::Test {
 protected:
  void SetUp() override {
    file_ = std::tmpfile();
    ASSERT_NE(file_, nullptr);
  }
  void TearDown() override { std::fclose(file_); }
  std::string Written() {
    std::fflush(file_);
    std::rewind(file_);
    std::string text;
    for (int c = std::fgetc(file_); c != EOF; c = std::fgetc(file_)) text += static_cast<char>(c);
    return text;
  }
  ProgressClock Clock() {
    return [this] { return start_ + std::chrono::milliseconds(now_ms_); };
  }
  std::FILE* file_ = nullptr;
  steady_clock::time_point start_{};
  long now_ms_ = 0;
};

// The line keeps its format ("runs 1/3  elapsed 2.0s  eta 10.0s"); the estimates are those of
// RemainingTimeTest worked by hand: 10 s after the cheapest run, 8 s x 2 / 4 = 4 s once the
// costliest is done too, 0 at the end.
TEST_F(ProgressOutputTest, TheLineShowsTheWeighedEstimate) {
  RunProgress progress({1, 2, 3}, true, "runs", start_, Clock(), file_);
  now_ms_ = 2000;
  progress.Finished(0);
  now_ms_ = 8000;
  progress.Finished(2);
  now_ms_ = 11000;
  progress.Finished(1);
  EXPECT_EQ(Written(),
            "runs 1/3  elapsed 2.0s  eta 10.0s\n"
            "runs 2/3  elapsed 8.0s  eta 4.0s\n"
            "runs 3/3  elapsed 11.0s  eta 0.0s\n");
}

// Done(n) hands on the first n (in order, the distributed sweep's and the figures' way).
TEST_F(ProgressOutputTest, DoneCountsTheFirstItems) {
  RunProgress progress({1, 1, 2}, true, "figures", start_, Clock(), file_);
  now_ms_ = 4000;
  progress.Done(2);  // 2 of 4 units in 4 s: 2 units left, 4 s
  EXPECT_EQ(Written(), "figures 2/3  elapsed 4.0s  eta 4.0s\n");
}

// --quiet: nothing at all.
TEST_F(ProgressOutputTest, OffWritesNothing) {
  RunProgress progress({1, 2}, false, "runs", start_, Clock(), file_);
  progress.Finished(0);
  progress.Finished(1);
  const PhaseLog phases(false, start_, Clock(), file_);
  phases.Start("inputs: generating the deployment's descriptors");
  EXPECT_EQ(Written(), "");
}

// A step's line says what starts and when (since the log's start).
TEST_F(ProgressOutputTest, APhaseLineNamesTheStep) {
  const PhaseLog phases(true, start_, Clock(), file_);
  now_ms_ = 6600;
  phases.Start("figures: drawing them");
  EXPECT_EQ(Written(), "figures: drawing them  elapsed 6.6s\n");
}

// The model's cost of each run (sweep_size.h), by hand for 1000 frames of dim 16 on the default
// network (point-to-point, no failover, no store-and-forward, 25000-byte verification requests):
// every run searches 1000^2 / 2 x 16 multiply-adds at 1e-10 s = 0.0008 s; a sim run adds its
// queries' and replies' copies, 2 x 1000 x n at 1e-6 s (0.004 s for 2 robots, 0.008 s for 4), and
// 1000 requests of 25000 bytes at 5e-10 s a byte (0.0125 s). The paper protocol sends nothing.
TEST(RunSecondsTest, EachRunCostsWhatTheModelGivesItsProtocolAndTeam) {
  const ExperimentConfig c = ParseConfig("robots: [2, 4]\nruns: 1\nprotocols: [paper, sim]\n", DVPR_SOURCE_DIR, {},
                                         "c.yaml");
  Dataset deployment;
  deployment.descriptors = DescriptorMatrix::Zero(1000, 16);
  std::vector<RunSpec> specs(4);
  specs[0].protocol = "paper";
  specs[0].robots = 2;
  specs[1].protocol = "sim";
  specs[1].robots = 2;
  specs[2].protocol = "sim";
  specs[2].robots = 4;
  specs[3].protocol = "paper";
  specs[3].robots = 4;
  const std::vector<double> seconds = RunSeconds(c, deployment, specs);
  ASSERT_EQ(seconds.size(), 4U);
  EXPECT_NEAR(seconds[0], 0.0008, 1e-12);
  EXPECT_NEAR(seconds[1], 0.0008 + 0.004 + 0.0125, 1e-12);
  EXPECT_NEAR(seconds[2], 0.0008 + 0.008 + 0.0125, 1e-12);
  EXPECT_NEAR(seconds[3], 0.0008, 1e-12);
}

}  // namespace
}  // namespace dvpr
