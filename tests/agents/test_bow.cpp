// Bag-of-words vectors, DBoW2's L1 score, the word-to-robot assignments, the vote of the
// distributed inverted index and the partial query's LCM size (agents/algorithms/bow_vector.h,
// agents/algorithms/bow_words.h, agents/messages/bow_query.h). Every expected number is worked by hand below.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "agents/messages/bow_query.h"
#include "agents/algorithms/bow_vector.h"
#include "agents/algorithms/bow_words.h"
#include "agents/messages/lcm_codec.h"

namespace dvpr {
namespace {

// A tiny vocabulary of 4 words and 3 documents of 4 features each:
//   A = [0, 0, 1, 2]  tf: w0 2/4 = 0.5,  w1 1/4 = 0.25, w2 0.25
//   B = [0, 1, 1, 1]  tf: w0 0.25, w1 0.75
//   C = [3, 0, 3, 3]  tf: w0 0.25, w3 0.75
// Documents containing each word: w0 3, w1 2, w2 1, w3 1, so with N = 3
//   idf(w0) = ln(3/3) = 0, idf(w1) = ln(1.5) = 0.4054651081081644, idf(w2) = idf(w3) = ln 3 = 1.0986122886681098.
// tf-idf of A: w0 0 (dropped), w1 0.25 x 0.4054651 = 0.1013662770, w2 0.25 x 1.0986123 = 0.2746530722;
//   sum 0.3760193492, so A = {w1: 0.2695772897, w2: 0.7304227103}.
// B: only w1 is left (0.75 x 0.4054651 = 0.3040988) -> {w1: 1}. C: only w3 -> {w3: 1}.
class TinyVocabulary : public ::testing::Test {
 protected:
  std::vector<BowVector> tf{TermFrequencies(std::vector<std::int32_t>{0, 0, 1, 2}),
                            TermFrequencies(std::vector<std::int32_t>{0, 1, 1, 1}),
                            TermFrequencies(std::vector<std::int32_t>{3, 0, 3, 3})};
};

TEST_F(TinyVocabulary, TermFrequencies) {
  EXPECT_EQ(tf[0], (BowVector{{0, 0.5f}, {1, 0.25f}, {2, 0.25f}}));
  EXPECT_EQ(tf[2], (BowVector{{0, 0.25f}, {3, 0.75f}}));
}

TEST_F(TinyVocabulary, InverseDocumentFrequency) {
  const std::vector<double> idf = InverseDocumentFrequency(tf, 5);
  ASSERT_EQ(idf.size(), 5u);
  EXPECT_DOUBLE_EQ(idf[0], 0.0);
  EXPECT_NEAR(idf[1], 0.4054651081081644, 1e-15);
  EXPECT_NEAR(idf[2], 1.0986122886681098, 1e-15);
  EXPECT_NEAR(idf[3], 1.0986122886681098, 1e-15);
  EXPECT_DOUBLE_EQ(idf[4], 0.0);  // in no document
}

TEST_F(TinyVocabulary, TfIdfWeightsAreL1Normalised) {
  const std::vector<double> idf = InverseDocumentFrequency(tf, 4);
  const BowVector a = WeightTfIdf(tf[0], idf);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].word, 1);
  EXPECT_NEAR(a[0].weight, 0.2695772897, 1e-7);
  EXPECT_EQ(a[1].word, 2);
  EXPECT_NEAR(a[1].weight, 0.7304227103, 1e-7);
  EXPECT_EQ(WeightTfIdf(tf[1], idf), (BowVector{{1, 1.0f}}));
  EXPECT_EQ(WeightTfIdf(tf[2], idf), (BowVector{{3, 1.0f}}));
}

// s(A, B) = 1 - 0.5 (|0.2695773 - 1| + |0.7304227 - 0|) = 1 - 0.5 x 1.4608454 = 0.2695773;
// A and C, B and C share no word: 1 - 0.5 x 2 = 0.
TEST_F(TinyVocabulary, L1ScoresOfTheDocuments) {
  const std::vector<double> idf = InverseDocumentFrequency(tf, 4);
  const BowVector a = WeightTfIdf(tf[0], idf), b = WeightTfIdf(tf[1], idf), c = WeightTfIdf(tf[2], idf);
  EXPECT_NEAR(L1Score(a, b), 0.2695772897, 1e-7);
  EXPECT_NEAR(L1Score(b, a), 0.2695772897, 1e-7);
  // Weights are float32: a normalised vector sums to 1 within ~1e-7, so "0" is 0 within that.
  EXPECT_NEAR(L1Score(a, c), 0.0, 1e-7);
  EXPECT_NEAR(L1Score(b, c), 0.0, 1e-7);
  EXPECT_NEAR(L1Score(a, a), 1.0, 1e-7);
}

// v = {1: 2, 2: 2} normalises to {0.5, 0.5}, w = {1: 1, 3: 3} to {0.25, 0.75}:
// |v - w|_1 = 0.25 + 0.5 + 0.75 = 1.5, s = 1 - 0.75 = 0.25 = min(0.5, 0.25) on the shared word 1.
TEST(BowScore, NormalisesBeforeScoring) {
  const BowVector v{{1, 2.0f}, {2, 2.0f}}, w{{1, 1.0f}, {3, 3.0f}};
  EXPECT_DOUBLE_EQ(L1Score(v, w), 0.25);
  EXPECT_DOUBLE_EQ(SharedMinimum(L1Normalised(v), L1Normalised(w)), 0.25);
  EXPECT_DOUBLE_EQ(L1Score(v, {}), 0.0);
}

TEST(WordOwners, ModuloRobots) {
  const WordOwners owners = WordOwners::Modulo(7, 3);
  EXPECT_EQ(owners.OwnerOf(0), RobotId(0));
  EXPECT_EQ(owners.OwnerOf(5), RobotId(2));
  EXPECT_EQ(owners.OwnerOf(6), RobotId(0));
  // {1: .2, 4: .3, 5: .5} -> robot 0 none, robot 1 words 1 and 4, robot 2 word 5.
  const auto parts = owners.Split(BowVector{{1, 0.2f}, {4, 0.3f}, {5, 0.5f}});
  ASSERT_EQ(parts.size(), 3u);
  EXPECT_TRUE(parts[0].empty());
  EXPECT_EQ(parts[1], (BowVector{{1, 0.2f}, {4, 0.3f}}));
  EXPECT_EQ(parts[2], (BowVector{{5, 0.5f}}));
}

// Document frequencies [5, 1, 4, 3, 2] on 2 robots, largest first: w0 (5) -> r0 (both 0, lower
// id), w2 (4) -> r1, w3 (3) -> r1 (4 < 5; now 7), w4 (2) -> r0 (5 < 7; now 7), w1 (1) -> r0
// (7 = 7, lower id).
TEST(WordOwners, ByDocumentFrequencyIsLpt) {
  const std::vector<std::int64_t> df{5, 1, 4, 3, 2};
  const WordOwners owners = WordOwners::ByDocumentFrequency(df, 2);
  const int expected[] = {0, 0, 1, 1, 0};
  for (int w = 0; w < 5; ++w) EXPECT_EQ(owners.OwnerOf(w), RobotId(expected[w])) << "word " << w;
  const std::vector<BowVector> docs{{{0, 1.f}, {2, 1.f}}, {{0, 1.f}}};
  EXPECT_EQ(DocumentFrequency(docs, 3), (std::vector<std::int64_t>{2, 0, 1}));
}

// Three robots answer a query with their partial best.
TEST(BowVote, MostConsistentFrameWins) {
  // Frame 10 from robots 0 and 1 (scores 0.2 + 0.1), frame 7 from robot 2 with a higher 0.5:
  // two votes beat one, whatever the score.
  const std::vector<PartialMatch> answers{{RobotId(0), RobotId(1), FrameId(10), 0.2},
                                          {RobotId(1), RobotId(1), FrameId(10), 0.1},
                                          {RobotId(2), RobotId(2), FrameId(7), 0.5}};
  const auto v = Vote(answers);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->frame, FrameId(10));
  EXPECT_EQ(v->match_robot, RobotId(1));
  EXPECT_EQ(v->votes, 2);
  EXPECT_DOUBLE_EQ(v->score, 0.2 + 0.1);
}

TEST(BowVote, TiesGoToTheHigherScoreThenTheLowerFrame) {
  // One vote each; frames 9 and 2 both scored 0.3 > 0.2: the lower frame id, 2.
  const std::vector<PartialMatch> answers{{RobotId(0), RobotId(0), FrameId(4), 0.2},
                                          {RobotId(1), RobotId(0), FrameId(9), 0.3},
                                          {RobotId(2), RobotId(1), FrameId(2), 0.3}};
  const auto v = Vote(answers);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->frame, FrameId(2));
  EXPECT_EQ(v->votes, 1);
  // Any order of the answers gives the same frame.
  const std::vector<PartialMatch> reversed(answers.rbegin(), answers.rend());
  EXPECT_EQ(Vote(reversed)->frame, FrameId(2));
  EXPECT_FALSE(Vote({}));
}

// bow_query_t by LCM's rules: fingerprint 8, utime int64 8, robot int16 2, frame int32 4,
// count int32 4, then count int32 words and count floats: 26 + 8 count bytes.
TEST(BowQueryMessage, EncodedSizeFollowsLcmRules) {
  EXPECT_EQ(EncodedBowQueryBytes({}), 26);
  EXPECT_EQ(EncodedBowQueryBytes(BowVector{{1, 0.5f}}), 34);
  EXPECT_EQ(EncodedBowQueryBytes(BowVector{{1, 0.5f}, {7, 0.25f}, {70000, 0.25f}}), 50);
  std::vector<BowEntry> many(400, BowEntry{3, 0.1f});
  EXPECT_EQ(EncodedBowQueryBytes(many), 26 + 8 * 400);
}

TEST(BowQueryMessage, FieldsAreBigEndianAtTheirOffsets) {
  const BowVector part{{1, 0.5f}, {70000, 0.25f}};
  const auto buf = Encode(MakeBowQuery(RobotId(3), FrameId(258), part, SimTime::Millis(2)));
  ASSERT_EQ(buf.size(), 42u);
  // utime 2000 us at 8..15, robot 3 at 16..17, frame 258 = 0x0102 at 18..21, count 2 at 22..25.
  EXPECT_EQ(buf[14], 0x07);
  EXPECT_EQ(buf[15], 0xD0);
  EXPECT_EQ(buf[17], 3);
  EXPECT_EQ(buf[20], 0x01);
  EXPECT_EQ(buf[21], 0x02);
  EXPECT_EQ(buf[25], 2);
  // words at 26..33: 1, then 70000 = 0x00011170; weights at 34..41: 0.5f = 0x3F000000, 0.25f = 0x3E800000.
  EXPECT_EQ(buf[29], 1);
  EXPECT_EQ(buf[31], 0x01);
  EXPECT_EQ(buf[32], 0x11);
  EXPECT_EQ(buf[33], 0x70);
  EXPECT_EQ(buf[34], 0x3F);
  EXPECT_EQ(buf[38], 0x3E);
  EXPECT_EQ(buf[39], 0x80);
  const auto back = Decode<bow_query_t>(buf);
  ASSERT_TRUE(back);
  EXPECT_EQ(BowPartOf(*back), part);
}

TEST(BowQueryMessage, GarbageCountIsRejectedBeforeDecoding) {
  auto buf = Encode(MakeBowQuery(RobotId(0), FrameId(0), BowVector{{1, 0.5f}}, SimTime()));
  buf[22] = 0x7F;  // count 0x7F000001: 16 GiB of entries claimed in a 34-byte buffer
  EXPECT_FALSE(Decode<bow_query_t>(buf));
  buf[22] = 0x80;  // negative
  EXPECT_FALSE(Decode<bow_query_t>(buf));
}

}  // namespace
}  // namespace dvpr
