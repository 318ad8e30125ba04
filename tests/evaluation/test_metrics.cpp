// PR curve and AUC exactly as docs/design.md section 2, on cases worked out by hand; balance ratio.
#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/domain/evaluation/metrics.h"
#include "tests/evaluation/evaluation_test_support.h"

namespace dvpr {
namespace {

constexpr double kR = 5.0;  // radius: a match is correct when it lies < 5 m from the query

using testing_support::OnLine;

MatchOutcome Match(int query, int match, double score) {
  return {FrameId(query), FrameId(match), score};
}
MatchOutcome NoCandidate(int query) { return {FrameId(query), std::nullopt, 0}; }

// Queries 0..4 and their possible matches 5..9. Query q sits at 100 q; frame 5 + q sits at
// 100 q + 1 (correct match for q) except frame 6, which sits at 100 + 50 (wrong for query 1).
const Positions kPlaces = OnLine({0, 100, 200, 300, 400, 1, 150, 201, 301, 401});

TEST(EvaluatePr, FiveQueriesByHand) {
  // q0 -> 5 (0.3, correct), q1 -> 6 (0.1, wrong), q2: no candidate, q3 -> 8 (0.3, correct),
  // q4 -> 9 (0.2, correct); R = 4 (q2 is relevant but got nothing).
  // Ranking by score, stable: q1 (F), q4 (T), q0 (T), q3 (T).
  //   k=1: TP 0 FP 1  P 0    R 0
  //   k=2: TP 1 FP 1  P 1/2  R 1/4
  //   k=3: TP 2 FP 1  P 2/3  R 2/4
  //   k=4: TP 3 FP 1  P 3/4  R 3/4
  // AUC = 1/4 * 1/2 + 1/4 * 2/3 + 1/4 * 3/4 = 23/48.
  const std::vector<MatchOutcome> log{Match(0, 5, 0.3), Match(1, 6, 0.1), NoCandidate(2),
                                      Match(3, 8, 0.3), Match(4, 9, 0.2)};
  const PrResult r = EvaluatePr(log, kPlaces, kR, 4);
  EXPECT_NEAR(r.auc, 23.0 / 48.0, 1e-11);
  EXPECT_EQ(r.ranked, 4);
  EXPECT_EQ(r.true_positives, 3);
  ASSERT_EQ(r.precision.size(), 4u);
  const std::vector<double> p{0, 0.5, 2.0 / 3, 0.75};
  const std::vector<double> rec{0, 0.25, 0.5, 0.75};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(r.precision[k], p[k], 1e-11) << k;
    EXPECT_NEAR(r.recall[k], rec[k], 1e-11) << k;
  }
}

TEST(EvaluatePr, PerfectRankingScoresOneMinusOneOverR) {
  // Three correct matches ranked before two wrong ones, R = 3:
  //   P = 1, 1, 1, 3/4, 3/5; recall = 1/3, 2/3, 1, 1, 1.
  // AUC sums from k = 2: 1/3 + 1/3 + 0 + 0 = 2/3 = (R-1)/R; the first step (0 -> 1/3) is not
  // counted by the formula, so a perfect ranking tends to 1 only as R grows.
  const std::vector<MatchOutcome> log{Match(0, 5, 1), Match(2, 7, 2), Match(3, 8, 3),
                                      Match(1, 6, 4), Match(4, 6, 5)};
  EXPECT_NEAR(EvaluatePr(log, kPlaces, kR, 3).auc, 2.0 / 3.0, 1e-11);
  // R = 1000 correct matches in order: AUC = 999/1000.
  std::vector<MatchOutcome> many;
  for (int i = 0; i < 1000; ++i) many.push_back(Match(0, 5, i));
  EXPECT_NEAR(EvaluatePr(many, kPlaces, kR, 1000).auc, 0.999, 1e-9);
}

TEST(EvaluatePr, TiesKeepTheInputOrder) {
  // Equal scores, one correct (q0 -> 5) and one wrong (q1 -> 6), R = 1.
  // Order T, F: P = 1, 1/2; recall = 1, 1  -> AUC = (1 - 1) * 1/2 = 0.
  // Order F, T: P = 0, 1/2; recall = 0, 1  -> AUC = (1 - 0) * 1/2 = 1/2.
  const std::vector<MatchOutcome> tf{Match(0, 5, 2.0), Match(1, 6, 2.0)};
  const std::vector<MatchOutcome> ft{Match(1, 6, 2.0), Match(0, 5, 2.0)};
  EXPECT_NEAR(EvaluatePr(tf, kPlaces, kR, 1).auc, 0.0, 1e-12);
  EXPECT_NEAR(EvaluatePr(ft, kPlaces, kR, 1).auc, 0.5, 1e-11);
}

TEST(EvaluatePr, QueryWithoutCandidateCountsOnlyInR) {
  // q0 -> 5 and q2 -> 7 correct (scores 1, 2); q3 relevant but without candidate; R = 3.
  // Ranked: P = 1, 1; recall = 1/3, 2/3 -> AUC = 1/3. Were q3 a ranked false positive, it would
  // add a third point; were it left out of R, recall would reach 1 and AUC would be 1/2.
  const std::vector<MatchOutcome> log{Match(0, 5, 1), Match(2, 7, 2), NoCandidate(3)};
  const PrResult r = EvaluatePr(log, kPlaces, kR, 3);
  EXPECT_EQ(r.ranked, 2);
  EXPECT_NEAR(r.recall.back(), 2.0 / 3.0, 1e-11);
  EXPECT_NEAR(r.auc, 1.0 / 3.0, 1e-11);
}

TEST(EvaluatePr, RelevantCountFromPositions) {
  // Frames at x = 0, 1, 2, 3, 0.5 with window 2: frame 0's candidates are 3, 4 (3 m and 0.5 m
  // away), frame 1: 4 (0.5 m), frame 2: none, frame 3: 0 (3 m), frame 4: 0, 1 (0.5 m each).
  // With r = 1 m: relevant are 0 (via 4), 1 (via 4), 4 (via 0): R = 3.
  // q0 -> 4 (score 1, correct) is the only outcome: P = 1, recall = 1/3, AUC = 0 (one point).
  const Positions p = OnLine({0, 1, 2, 3, 0.5});
  const std::vector<MatchOutcome> log{Match(0, 4, 1)};
  const PrResult r = EvaluatePr(log, p, GroundTruthParams{.radius_m = 1, .suppression_frames = 2});
  EXPECT_EQ(r.relevant, 3);
  EXPECT_NEAR(r.recall[0], 1.0 / 3.0, 1e-11);
  EXPECT_EQ(r.auc, 0.0);
}

TEST(EvaluatePr, RejectsBadLogs) {
  EXPECT_THROW(EvaluatePr(std::vector{Match(0, 5, std::nan(""))}, kPlaces, kR, 1),
               std::invalid_argument);
  EXPECT_THROW(EvaluatePr(std::vector{Match(0, 10, 1)}, kPlaces, kR, 1), std::invalid_argument);
  EXPECT_THROW(EvaluatePr(std::vector<MatchOutcome>{}, kPlaces, kR, -1), std::invalid_argument);
}

TEST(EvaluatePr, NoRelevantQueriesGiveZero) {
  // R = 0 and only wrong matches: recall 0 everywhere, AUC 0 (not NaN, thanks to the 1e-12).
  const PrResult r = EvaluatePr(std::vector{Match(1, 6, 1), Match(1, 6, 2)}, kPlaces, kR, 0);
  EXPECT_EQ(r.auc, 0.0);
}

TEST(RelativeAuc, DividesAndFlagsAZeroReference) {
  EXPECT_DOUBLE_EQ(RelativeAuc(0.3, 0.6), 0.5);
  EXPECT_TRUE(std::isnan(RelativeAuc(0.3, 0.0)));
}

TEST(WorstBalanceRatio, ByHand) {
  // 10 frames on 3 robots: N/n = 10/3; the busiest has 5: 5 / (10/3) = 1.5.
  EXPECT_DOUBLE_EQ(WorstBalanceRatio(std::vector<std::int64_t>{5, 3, 2}), 1.5);
  // Perfect balance is 1; everything on one of 4 robots is 4 (idle robots count in n).
  EXPECT_DOUBLE_EQ(WorstBalanceRatio(std::vector<std::int64_t>{7, 7, 7}), 1.0);
  EXPECT_DOUBLE_EQ(WorstBalanceRatio(std::vector<std::int64_t>{0, 9, 0, 0}), 4.0);
  EXPECT_TRUE(std::isnan(WorstBalanceRatio(std::vector<std::int64_t>{0, 0})));
}

TEST(CountPerRobot, CountsAndRejectsUnknownRobots) {
  const std::vector<RobotId> routes{RobotId(2), RobotId(0), RobotId(2), RobotId(2)};
  EXPECT_EQ(CountPerRobot(routes, 4), (std::vector<std::int64_t>{1, 0, 3, 0}));
  EXPECT_THROW(CountPerRobot(routes, 2), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
