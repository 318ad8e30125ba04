// Inter- and intra-robot queries, loop closures and first-closure times (docs/design.md section 3,
// "Inter-robot loop closures"), on two hand-made trajectories counted by hand.
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/domain/evaluation/sim_metrics.h"

namespace dvpr {
namespace {

constexpr double kRadius = 5.0;  // a match is correct when it lies < 5 m away
constexpr int kWindow = 2;       // frames |i - j| <= 2 apart never count

// The perimeter of a 40 m square, a point every 10 m: p(0) = (0, 0), p(4) = (40, 0),
// p(8) = (40, 40), p(12) = (0, 40), p(16) = p(0).
Eigen::Vector3d Perimeter(int k) {
  k %= 16;
  if (k <= 4) return {10.0 * k, 0, 0};
  if (k <= 8) return {40, 10.0 * (k - 4), 0};
  if (k <= 12) return {40 - 10.0 * (k - 8), 40, 0};
  return {0, 40 - 10.0 * (k - 12), 0};
}

// Robot 0 drives the square once, frames 0..16 at p(0..16), taken at 0..16 s; robot 1 drives it
// the other way round 30 s later, frames 17..33 at p(16), p(15), ..., p(0), taken at 30..46 s.
// Robot 2 takes nothing.
struct TwoSquares {
  Positions positions = Positions::Zero(34, 3);
  std::vector<SimTime> capture;
  std::vector<RobotId> taker;
  std::vector<QueryRecord> queries;

  TwoSquares() {
    for (int f = 0; f < 34; ++f) {
      const bool second = f >= 17;
      const int m = second ? f - 17 : f;
      positions.row(f) = Perimeter(second ? 16 - m : m).transpose();
      capture.push_back(SimTime::Seconds(second ? 30 + m : m));
      taker.emplace_back(second ? 1 : 0);
      QueryRecord q;
      q.robot = taker.back();
      q.frame = FrameId(f);
      q.sent = capture.back();
      queries.push_back(q);
    }
  }
  void Answer(int query, int robot, int match, float distance, bool verify, std::optional<bool> accepted) {
    QueryRecord& q = queries[static_cast<std::size_t>(query)];
    q.best = IndexMatch{RobotId(robot), FrameId(match), distance};
    q.verify_requested = verify;
    q.verify_accepted = accepted;
  }
};

TEST(ClosuresTest, SquareAndItsReverseClassedByHand) {
  const TwoSquares w;
  const OnlineTruth truth = ComputeOnlineTruth(w.queries, w.positions, w.capture, w.taker, kRadius, kWindow);
  // Robot 0's frames 0..15 lie 10 m from each other: nothing near, not relevant. Frame 16 is back
  // at p(0): frame 0 (its own) -> intra. Robot 1 goes after robot 0 has passed every corner: each
  // of its frames lies on one of robot 0's -> inter (frame 33, at p(0), also has its own frame 17,
  // but one of another robot's makes it inter). Frame 17's nearest of robot 0 is frame 16, one
  // frame away (inside the window), but frame 0 counts.
  for (int f = 0; f < 34; ++f) {
    const QueryClass expected = f < 16 ? QueryClass::kNotRelevant
                                : f == 16 ? QueryClass::kIntraRobot
                                          : QueryClass::kInterRobot;
    EXPECT_EQ(truth.query_class[static_cast<std::size_t>(f)], expected) << "frame " << f;
    EXPECT_EQ(truth.relevant[static_cast<std::size_t>(f)], f >= 16) << "frame " << f;
  }
  EXPECT_STREQ(QueryClassName(truth.query_class[16]), "intra");
  EXPECT_STREQ(QueryClassName(truth.query_class[17]), "inter");
  EXPECT_STREQ(QueryClassName(truth.query_class[0]), "");
}

TEST(ClosuresTest, CountsAurocAndFirstClosureByHand) {
  TwoSquares w;
  // Frame 16 (robot 0) -> its own frame 0: correct, verified (an intra-robot closure).
  w.Answer(16, 0, 0, 0.5f, true, true);
  // Frame 17 (robot 1, 30 s, at p(0)) -> robot 0's frame 0: correct, verified: the pair's first.
  w.Answer(17, 0, 0, 0.1f, true, true);
  // Frame 20 (robot 1, 33 s, at p(13) = (0, 30)) -> robot 0's frame 5 at (40, 10): wrong,
  // verification asked and refused.
  w.Answer(20, 0, 5, 0.2f, true, false);
  // Frame 25 (robot 1, 38 s, at p(8)) -> robot 0's frame 8: correct, no verification asked.
  w.Answer(25, 0, 8, 0.3f, false, std::nullopt);
  // Frame 30 (robot 1, 43 s, at p(3)) -> robot 0's frame 3: correct, verified, later than 17's.
  w.Answer(30, 0, 3, 0.4f, true, true);
  const OnlineTruth truth = ComputeOnlineTruth(w.queries, w.positions, w.capture, w.taker, kRadius, kWindow);
  const ClosureStats s = ComputeClosures(w.queries, truth, w.positions, w.taker, kRadius, 3);
  EXPECT_EQ(s.inter_queries, 17);
  EXPECT_EQ(s.intra_queries, 1);
  EXPECT_EQ(s.inter_recognised, 3);  // 17, 25, 30
  EXPECT_EQ(s.intra_recognised, 1);
  // Inter, by distance: 17 (0.1, T), 20 (0.2, F), 25 (0.3, T), 30 (0.4, T); R = 17. The AUC of
  // section 2 (the authors' code) sums (R_k - R_k-1) P_k from the second ranked query on:
  //   P 1, 1/2, 2/3, 3/4 at R 1/17, 1/17, 2/17, 3/17 -> 0 x 1/2 + 1/17 x 2/3 + 1/17 x 3/4 = 1/12.
  EXPECT_NEAR(s.inter_auc, 1.0 / 12.0, 1e-12);
  EXPECT_EQ(s.intra_auc, 0.0);  // one ranked query: no step after the first
  EXPECT_EQ(s.inter_candidates, 3);  // 17, 20, 30 (16's is its own robot's frame)
  EXPECT_EQ(s.inter_closures, 2);    // 17, 30
  ASSERT_EQ(s.pairs.size(), 3u);     // (0, 1), (0, 2), (1, 2)
  EXPECT_EQ(s.pairs[0].a, RobotId(0));
  EXPECT_EQ(s.pairs[0].b, RobotId(1));
  ASSERT_TRUE(s.pairs[0].first.has_value());
  EXPECT_EQ(*s.pairs[0].first, SimTime::Seconds(30));
  EXPECT_EQ(s.pairs[1].b, RobotId(2));
  EXPECT_FALSE(s.pairs[1].first.has_value());
  EXPECT_FALSE(s.pairs[2].first.has_value());
  EXPECT_EQ(MedianFirstClosure(s.pairs), SimTime::Seconds(30));
}

TEST(ClosuresTest, MedianFirstClosureOfOddAndEvenCounts) {
  const auto pair = [](std::optional<std::int64_t> ns) {
    return PairClosure{RobotId(0), RobotId(1), ns ? std::optional(SimTime::Nanos(*ns)) : std::nullopt};
  };
  EXPECT_FALSE(MedianFirstClosure({}).has_value());
  EXPECT_FALSE(MedianFirstClosure({pair(std::nullopt)}).has_value());
  // 7, 3, (none), 5 -> 3, 5, 7: 5.
  EXPECT_EQ(MedianFirstClosure({pair(7), pair(3), pair(std::nullopt), pair(5)}), SimTime::Nanos(5));
  // 10, 1, 4, 8 -> 1, 4, 8, 10: (4 + 8) / 2 = 6; 1, 4 -> 2 (2.5 floored).
  EXPECT_EQ(MedianFirstClosure({pair(10), pair(1), pair(4), pair(8)}), SimTime::Nanos(6));
  EXPECT_EQ(MedianFirstClosure({pair(4), pair(1)}), SimTime::Nanos(2));
}

TEST(ClosuresTest, MismatchedSizesAreRefused) {
  const TwoSquares w;
  std::vector<RobotId> short_taker(w.taker.begin(), w.taker.end() - 1);
  EXPECT_THROW(ComputeOnlineTruth(w.queries, w.positions, w.capture, short_taker, kRadius, kWindow),
               std::invalid_argument);
  OnlineTruth truth = ComputeOnlineTruth(w.queries, w.positions, w.capture, w.taker, kRadius, kWindow);
  truth.query_class.pop_back();
  EXPECT_THROW(ComputeClosures(w.queries, truth, w.positions, w.taker, kRadius, 3), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
