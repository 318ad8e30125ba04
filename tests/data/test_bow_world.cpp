// The two weaknesses of local features the synthetic BoW world models on request
// (experiments/domain/data/synthetic_bow.h, docs/bow.md): perceptual aliasing (common_words,
// common_share) and viewpoint sensitivity (view_sector_deg), each on a small world worked by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/domain/data/synthetic_bow.h"
#include "tests/data/bow_test_support.h"

namespace dvpr {
namespace {

// Frames given as (x, z, heading angle in the x-z plane).
Trajectory Frames(const std::vector<std::array<double, 3>>& frames) {
  const auto n = static_cast<Eigen::Index>(frames.size());
  Trajectory t{Positions(n, 3), Headings(n, 3)};
  Eigen::Index i = 0;
  for (const auto& f : frames) {
    t.positions.row(i) << f[0], 1.5, f[1];
    t.headings.row(i) << std::cos(f[2]), 0.0, std::sin(f[2]);
    ++i;
  }
  return t;
}

using testing_support::SharedWords;

class BowWorldTest : public ::testing::Test {
 protected:
  BowWorldTest() {
    appearance_.noise = 0.0;  // no quantisation noise: every word is a landmark's or a common one
    bow_.features = 300;
    bow_.vocabulary = 1000000;
  }
  // Ten million words: two frames of about 200 distinct landmark words each collide on one by
  // chance with probability about 200 x 200 / 10^7 = 0.004, so a shared word is a shared landmark.
  void NoChanceCollisions() { bow_.vocabulary = 10000000; }
  // 20 places 100 m apart (farther than range_m, 40: no landmark seen from two of them), each
  // passed twice facing +x: frames 0..19, then 20..39 at the same places.
  static Trajectory TwoPasses() {
    std::vector<std::array<double, 3>> f;
    for (int pass = 0; pass < 2; ++pass) {
      for (int k = 0; k < 20; ++k) f.push_back({100.0 * k, 0.0, 0.0});
    }
    return Frames(f);
  }
  // How many of the first pass's 20 frames have their revisit (frame + 20) as best L1 match.
  int RevisitsFound(const std::vector<std::vector<std::int32_t>>& words) const {
    const BowData data = TfIdfFromWords(words, bow_.vocabulary);
    int found = 0;
    for (int q = 0; q < 20; ++q) {
      int best = -1;
      double best_score = -1.0;
      for (int f = 0; f < 40; ++f) {
        if (f == q) continue;
        const double s = L1Score(data.frames[static_cast<std::size_t>(q)], data.frames[static_cast<std::size_t>(f)]);
        if (s > best_score) best = f, best_score = s;
      }
      found += best == q + 20 ? 1 : 0;
    }
    return found;
  }
  SyntheticParams appearance_;
  SyntheticBowParams bow_;
};

// common_share 1: every feature is one of the common words, drawn the same way wherever the
// frame is, so a frame's words hold nothing of its place: frame k at any place has the same words.
TEST_F(BowWorldTest, OnlyCommonWordsCarryNothingOfThePlace) {
  bow_.common_words = 1000;
  bow_.common_share = 1.0;
  const auto here = SyntheticBowWords(Frames({{0, 0, 0}, {5, 0, 0}}), appearance_, bow_, 11);
  const auto there = SyntheticBowWords(Frames({{700, -300, 2}, {-50, 90, 1}}), appearance_, bow_, 11);
  EXPECT_EQ(here, there);
  for (const auto& frame : here) {
    ASSERT_EQ(frame.size(), 300u);
    for (std::int32_t w : frame) EXPECT_TRUE(w >= 0 && w < 1000) << w;
  }
}

// The place with only common words is matched no better than chance: each query's best of its 39
// other frames is its revisit with probability 1/39, about 0.5 of the 20 queries (3 or more has
// probability below 2 %; the seed is fixed). Its landmarks alone (common_share 0) find all 20.
TEST_F(BowWorldTest, APlaceOfOnlyCommonWordsIsMatchedNoBetterThanChance) {
  const Trajectory t = TwoPasses();
  EXPECT_EQ(RevisitsFound(SyntheticBowWords(t, appearance_, bow_, 5)), 20);
  bow_.common_words = 1000;
  bow_.common_share = 1.0;
  EXPECT_LE(RevisitsFound(SyntheticBowWords(t, appearance_, bow_, 5)), 2);
}

// Half the features common: each frame still has about 150 landmark features and finds its revisit
// (the common words, in roughly every frame alike, weigh little after idf), yet the frames of
// different places now share words (150 draws hit about 139 of the 1000, so two frames share
// about 139 x 139 / 1000 = 19 in expectation; at least 5 here).
TEST_F(BowWorldTest, CommonWordsAreSharedByDifferentPlaces) {
  bow_.common_words = 1000;
  bow_.common_share = 0.5;
  const Trajectory t = TwoPasses();
  const auto w = SyntheticBowWords(t, appearance_, bow_, 5);
  EXPECT_EQ(RevisitsFound(w), 20);
  EXPECT_GE(SharedWords(w[0], w[7]), 5u);
  bow_.common_share = 0.0;
  const auto without = SyntheticBowWords(t, appearance_, bow_, 5);
  EXPECT_EQ(SharedWords(without[0], without[7]), 0u);
}

// Frame 0 at the origin faces +x; frame 1, 20 m further, faces back (-x): both fields of view
// (90 degrees) hold the landmarks of the square with corners (0, 0), (10, +-10), (20, 0), 200 m^2,
// about 40 landmarks at the default density 0.2. A landmark in both views is seen from directions
// at least 180 - 90 = 90 degrees apart (each within 45 degrees of its camera's heading, the
// headings opposite), so with view_sector_deg 80 <= 90 no landmark shows both cameras the same
// word; with 360 (one word from everywhere) they share some of those 40.
TEST_F(BowWorldTest, ARevisitFromTheOppositeHeadingSharesNoDistinctiveWord) {
  NoChanceCollisions();
  const Trajectory t = Frames({{0, 0, 0}, {20, 0, std::numbers::pi}, {0, 0, std::numbers::pi}, {2, 0, 0}});
  const auto everywhere = SyntheticBowWords(t, appearance_, bow_, 9);
  EXPECT_GT(SharedWords(everywhere[0], everywhere[1]), 5u);
  bow_.view_sector_deg = 80;
  const auto sectors = SyntheticBowWords(t, appearance_, bow_, 9);
  EXPECT_EQ(SharedWords(sectors[0], sectors[1]), 0u);
  EXPECT_EQ(SharedWords(sectors[0], sectors[2]), 0u);  // the same place, facing the other way
  // 2 m on, the same heading: the viewing directions turn by a few degrees, most words stay.
  EXPECT_GT(SharedWords(sectors[0], sectors[3]), 50u);
}

// The word changes with the viewpoint: cameras 15 m from the origin, each facing it with a
// narrow field of view (10 degrees, range 20 m: a thin wedge through the origin), one at 0 degrees
// round, one at 5 and one at 90. The landmarks near the origin are in all three wedges; the first
// two see them from directions about 5 degrees apart, most within one sector of 60 degrees (same
// word), the third from about 90 degrees away, more than a sector: never the same word.
TEST_F(BowWorldTest, ALandmarkWordChangesWithTheViewingDirection) {
  NoChanceCollisions();
  bow_.view_sector_deg = 60;
  bow_.range_m = 20;
  bow_.field_of_view_deg = 10;
  bow_.landmark_density = 5;  // a wedge of 10 degrees and 20 m is 35 m^2: about 175 landmarks in view
  const auto at = [](double deg) {
    const double a = deg * std::numbers::pi / 180.0;
    return std::array<double, 3>{15 * std::cos(a), 15 * std::sin(a), a + std::numbers::pi};
  };
  const auto w = SyntheticBowWords(Frames({at(0), at(5), at(90)}), appearance_, bow_, 4);
  EXPECT_GT(SharedWords(w[0], w[1]), 20u);
  EXPECT_EQ(SharedWords(w[0], w[2]), 0u);
  bow_.view_sector_deg = 360;  // one word from every direction: the third camera shares the origin's
  const auto everywhere = SyntheticBowWords(Frames({at(0), at(5), at(90)}), appearance_, bow_, 4);
  EXPECT_GT(SharedWords(everywhere[0], everywhere[2]), 0u);
}

TEST_F(BowWorldTest, ValidateNamesTheFieldAndTheRange) {
  const auto error = [](SyntheticBowParams p) {
    try {
      p.Validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  SyntheticBowParams p;
  p.common_share = 1.5;
  EXPECT_EQ(error(p), "common_share: must be in [0, 1]");
  p.common_share = 0.5;
  EXPECT_EQ(error(p), "common_share: needs common_words >= 1 when above 0");
  p.common_words = 100000;  // the whole default vocabulary: no word left for the landmarks
  EXPECT_EQ(error(p), "common_words: must be in [0, vocabulary - 1 = 99999], got 100000");
  p.common_words = 10;
  p.view_sector_deg = 0;
  EXPECT_EQ(error(p), "view_sector_deg: must be in (0, 360]");
  p.view_sector_deg = 360;
  EXPECT_EQ(error(p), "no error");
}

}  // namespace
}  // namespace dvpr
