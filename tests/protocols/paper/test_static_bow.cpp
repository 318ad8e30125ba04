// Bag-of-words in the static protocol (experiments/protocols/paper/static_bow.h) on six frames
// whose scores, votes, AUCs and message sizes are worked out by hand.
#include <gtest/gtest.h>

#include "experiments/protocols/paper/static_bow.h"

namespace dvpr {
namespace {

// Frames at x = 0 100 200 1 101 300 (frames 3 and 4 revisit 0 and 1), window 1, r = 5 m:
// relevant are 0, 1, 3, 4 (R = 4). Two robots: robot 0 took frames 0-2, robot 1 frames 3-5.
// BoW vectors (already L1-normalised) over words 0..5:
//   f0 {0: .5, 1: .5}   f1 {2: .5, 3: .5}   f2 {5: 1}
//   f3 {0: .6, 1: .4}   f4 {2: .3, 3: .3, 5: .4}   f5 {4: 1}
// Centralized L1 scores (sum of minima over shared words), candidates |i - j| > 1:
//   f0 -> f3 .9 (correct)  f1 -> f4 .6 (correct)  f2 -> f4 .4 (wrong: 200 vs 101)
//   f3 -> f0 .9 (correct)  f4 -> f1 .6 (correct, f2 scores .4)  f5: no shared word, no match.
// Ranked by 1 - score: f0 .1, f3 .1, f1 .4, f4 .4, f2 .6 -> tp 1 1 1 1 0, recall .25 .5 .75 1 1,
// precision 1 1 1 1 .8; AUC = sum over k >= 2 of (r_k - r_k-1) p_k = .25 + .25 + .25 + 0 = 0.75.
//
// Distributed index, word w owned by robot w mod 2 (even words robot 0, odd robot 1):
//   f4's parts: robot 0 {2: .3} -> best f1 (.3); robot 1 {3: .3, 5: .4} -> f1 .3, f2 .4 -> f2.
//   One vote each: the higher score, f2 (.4), wins: wrong, and not the centralized best f1.
//   f0, f1, f3 get two votes for their centralized best; f2's only part (robot 1) returns f4 (.4).
// Ranked: f0 .1, f3 .1, f1 .4, f2 .6, f4 .6 -> tp 1 1 1 0 0, recall .25 .5 .75 .75 .75,
// precision 1 1 1 .75 .6; AUC = .25 + .25 = 0.5, relative 0.5 / 0.75.
// Messages: each frame has exactly one entry for the robot that did not take it (f4: {2}), so
// six bow_query_t of 26 + 8 = 34 bytes, 204 bytes.
class StaticBowTest : public ::testing::Test {
 protected:
  StaticBowTest() {
    data_.descriptors = DescriptorMatrix::Ones(6, 2);
    data_.trajectory.positions = Positions::Zero(6, 3);
    data_.trajectory.positions.col(0) << 0, 100, 200, 1, 101, 300;
    data_.trajectory.headings = Positions::Zero(6, 3);
    data_.trajectory.headings.col(2).setOnes();
    bow_.vocabulary = 6;
    bow_.frames = {{{0, .5f}, {1, .5f}}, {{2, .5f}, {3, .5f}}, {{5, 1.f}},
                        {{0, .6f}, {1, .4f}}, {{2, .3f}, {3, .3f}, {5, .4f}}, {{4, 1.f}}};
  }
  Dataset data_;
  BowData bow_;
};

TEST_F(StaticBowTest, CentralizedRanking) {
  const PaperEvaluator paper(data_, {.radius_m = 5, .suppression_frames = 1}, 2, 1);
  ASSERT_EQ(paper.relevant(), 4);
  const BowEvaluator bow(paper, bow_);
  // Within 1e-9: precision and recall carry docs/design.md's + 1e-12 in their denominators.
  EXPECT_NEAR(bow.centralized().auc, 0.75, 1e-9);
  const BowRunResult broadcast = bow.Reference("bow_broadcast", 2, true);
  EXPECT_DOUBLE_EQ(broadcast.paper.row.relative_auc, 1.0);
  // The full vectors to the one other robot: 2, 2, 1, 2, 3, 1 entries = 42 42 34 42 50 34 bytes.
  EXPECT_EQ(broadcast.bow.partial_queries, 6);
  EXPECT_EQ(broadcast.bow.payload_bytes, 244);
  EXPECT_EQ(broadcast.part_sizes, (std::map<std::int64_t, std::int64_t>{{34, 2}, {42, 3}, {50, 1}}));
  EXPECT_EQ(broadcast.bow.part_bytes_p50, 42);
  EXPECT_EQ(broadcast.bow.part_bytes_max, 50);
}

TEST_F(StaticBowTest, DistributedIndexVotes) {
  const PaperEvaluator paper(data_, {.radius_m = 5, .suppression_frames = 1}, 2, 1);
  const BowEvaluator bow(paper, bow_);
  const BowRunResult r = bow.Evaluate(WordOwners::Modulo(6, 2), "bow_decentralized", false);
  EXPECT_NEAR(r.paper.row.auc, 0.5, 1e-9);
  EXPECT_NEAR(r.paper.row.auc_reference, 0.75, 1e-9);
  EXPECT_NEAR(r.paper.row.relative_auc, 0.5 / 0.75, 1e-9);
  EXPECT_EQ(r.bow.voted, 5);
  EXPECT_EQ(r.bow.vote_not_centralized, 1);
  EXPECT_EQ(r.bow.partial_queries, 6);
  EXPECT_EQ(r.bow.payload_bytes, 204);
  EXPECT_EQ(r.paper.row.payload_bytes, 204);
  EXPECT_EQ(r.part_sizes, (std::map<std::int64_t, std::int64_t>{{34, 6}}));
  // Parts served: robot 0 (even words) all but f2, robot 1 (odd words or 5) all but f5.
  ASSERT_EQ(r.paper.per_robot.size(), 2u);
  EXPECT_EQ(r.paper.per_robot[0].queries_received, 5);
  EXPECT_EQ(r.paper.per_robot[1].queries_received, 5);
}

}  // namespace
}  // namespace dvpr
