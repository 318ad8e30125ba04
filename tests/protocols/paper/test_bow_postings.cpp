// The static protocol's BoW search (experiments/protocols/paper/bow_postings.h) and the batched
// evaluation (BowEvaluator::EvaluateMany, EvaluatePlanned) against the definitions they shortcut:
// every score is SharedMinimum's to the last bit (the same sum in the same order), the best
// frame the highest score outside the window with ties to the lower frame, and the work the
// postings of the frames outside the window. Whether a search remembers the frames it touched or
// looks at every frame (few or many postings) must not change any of it; both happen below.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <set>

#include "experiments/protocols/paper/bow_postings.h"
#include "experiments/protocols/paper/static_bow.h"

namespace dvpr {
namespace {

// 300 frames of 1 to 30 words from a vocabulary of 200, weights drawn and L1-normalised, and a
// few ties made on purpose: frames 40 and 41 are copies of frame 10 (so every query that finds
// one of them finds all three at one score).
BowData RandomWorld() {
  std::mt19937 rng(7);
  BowData bow;
  bow.vocabulary = 200;
  for (int f = 0; f < 300; ++f) {
    std::set<std::int32_t> words;
    const int count = 1 + static_cast<int>(rng() % 30);
    while (static_cast<int>(words.size()) < count) words.insert(static_cast<std::int32_t>(rng() % 200));
    BowVector v;
    for (const std::int32_t w : words) v.push_back({w, 0.1f + static_cast<float>(rng() % 1000) / 997.0f});
    bow.frames.push_back(L1Normalised(v));
  }
  bow.frames[40] = bow.frames[10];
  bow.frames[41] = bow.frames[10];
  return bow;
}

struct Expected {
  std::int32_t frame = -1;
  double score = 0.0;
  std::int64_t visited = 0;
};

// The definition: every frame outside the window, scored with SharedMinimum.
Expected BruteForce(const BowData& bow, std::int32_t query, int window, const BowVector& part) {
  Expected e;
  for (std::int32_t j = 0; j < static_cast<std::int32_t>(bow.frames.size()); ++j) {
    if (std::abs(j - query) <= window) continue;
    const double s = SharedMinimum(part, bow.frames[static_cast<std::size_t>(j)]);
    if (s > e.score) e = {j, s, e.visited};
    for (const BowEntry& q : part) {
      const BowVector& f = bow.frames[static_cast<std::size_t>(j)];
      e.visited += std::any_of(f.begin(), f.end(), [&](const BowEntry& x) { return x.word == q.word; }) ? 1 : 0;
    }
  }
  return e;
}

TEST(BowPostingsTest, EverySearchIsTheDefinitionToTheLastBit) {
  const BowData bow = RandomWorld();
  const BowPostings postings(bow);
  BowPostings::Scratch scratch(bow.frames.size());
  const WordOwners owners = WordOwners::Modulo(bow.vocabulary, 7);
  const int window = 5;
  int tied = 0;
  for (std::int32_t i = 0; i < 300; ++i) {
    const BowVector& v = bow.frames[static_cast<std::size_t>(i)];
    // The whole vector (about 15 words of about 22 postings: many, every frame looked at), then
    // each part of w mod 7 (a word or two: few, the touched frames only).
    std::vector<BowVector> parts = owners.Split(v);
    parts.insert(parts.begin(), v);
    for (const BowVector& part : parts) {
      std::vector<BowPostings::Run> runs;
      postings.AppendRuns(part, i, window, runs);
      std::int64_t visited = 0;
      const BowPostings::Best got = postings.Search(i, window, runs, scratch, visited);
      const Expected want = BruteForce(bow, i, window, part);
      ASSERT_EQ(got.frame, want.frame) << "query " << i;
      ASSERT_EQ(got.score, want.score) << "query " << i;  // exactly: the same sum in the same order
      ASSERT_EQ(visited, want.visited) << "query " << i;
      if (got.frame == 10 && i > 41 + window) ++tied;  // 10, 40 and 41 tie: the lowest wins
    }
  }
  EXPECT_GT(tied, 0);
}

TEST(BowPostingsTest, BatchedAndPlannedEvaluationsAreEachOnesOwn) {
  const BowData bow = RandomWorld();
  Dataset data;
  data.descriptors = DescriptorMatrix::Ones(300, 2);
  data.trajectory.positions = Positions::Zero(300, 3);
  for (int f = 0; f < 300; ++f) data.trajectory.positions(f, 0) = (f % 100) * 10.0;  // three laps
  data.trajectory.headings = Positions::Zero(300, 3);
  data.trajectory.headings.col(2).setOnes();
  const PaperEvaluator paper(data, {.radius_m = 5, .suppression_frames = 5}, 2, 1);
  BowEvaluator evaluator(paper, bow);
  const WordOwners mod2 = WordOwners::Modulo(bow.vocabulary, 2), mod7 = WordOwners::Modulo(bow.vocabulary, 7);
  const WordOwners df3 = WordOwners::ByDocumentFrequency(DocumentFrequency(bow.frames, bow.vocabulary), 3);
  const std::vector<BowEvaluator::Assignment> assignments = {{&mod2, "a"}, {&mod7, "b"}, {&df3, "c"}};
  const std::vector<BowRunResult> batched = evaluator.EvaluateMany(assignments, false);
  ASSERT_EQ(batched.size(), 3u);
  evaluator.Plan({{"b", 7, [&] { return std::make_shared<const WordOwners>(mod7); }},
                  {"c", 3, [&] { return std::make_shared<const WordOwners>(df3); }}});
  EXPECT_TRUE(evaluator.IsPlanned("b", 7));
  EXPECT_FALSE(evaluator.IsPlanned("b", 3));
  EXPECT_THROW(evaluator.EvaluatePlanned("a", 2), std::logic_error);
  const BowRunResult planned_c = evaluator.EvaluatePlanned("c", 3);
  const BowRunResult planned_b = evaluator.EvaluatePlanned("b", 7);  // evaluated with c's batch
  for (std::size_t a = 0; a < 3; ++a) {
    const BowRunResult alone = evaluator.Evaluate(*assignments[a].owners, assignments[a].name, false);
    const BowRunResult& together = batched[a];
    ASSERT_EQ(alone.matches.size(), 300u);
    for (std::size_t i = 0; i < 300; ++i) {
      EXPECT_EQ(alone.matches[i].match, together.matches[i].match);
      EXPECT_EQ(alone.matches[i].score, together.matches[i].score);
    }
    EXPECT_EQ(alone.paper.row.auc, together.paper.row.auc);
    EXPECT_EQ(alone.part_sizes, together.part_sizes);
    EXPECT_EQ(alone.bow.vote_not_centralized, together.bow.vote_not_centralized);
    ASSERT_EQ(alone.paper.per_robot.size(), together.paper.per_robot.size());
    for (std::size_t r = 0; r < alone.paper.per_robot.size(); ++r) {
      EXPECT_EQ(alone.paper.per_robot[r].comparisons, together.paper.per_robot[r].comparisons);
    }
    if (a == 0) continue;
    const BowRunResult& planned = a == 1 ? planned_b : planned_c;
    EXPECT_EQ(planned.paper.row.auc, alone.paper.row.auc);
    EXPECT_EQ(planned.part_sizes, alone.part_sizes);
    for (std::size_t i = 0; i < 300; ++i) EXPECT_EQ(planned.matches[i].match, alone.matches[i].match);
  }
}

}  // namespace
}  // namespace dvpr
