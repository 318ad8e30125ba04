// The synthetic bag-of-words model (experiments/domain/data/synthetic_bow.h) and users' own BoW files
// (experiments/domain/data/bow_file.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <set>
#include <string>

#include "experiments/domain/data/bow_file.h"
#include "experiments/domain/data/synthetic_bow.h"
#include "tests/data/bow_test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

// Frames given as (x, z, heading angle in the x-z plane).
Trajectory Frames(std::initializer_list<std::array<double, 3>> frames) {
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

class SyntheticBowTest : public ::testing::Test {
 protected:
  SyntheticBowTest() {
    bow_.features = 300;
    bow_.vocabulary = 10000;
  }
  SyntheticParams appearance_;
  SyntheticBowParams bow_;
};

TEST_F(SyntheticBowTest, FeaturesPerFrameAndWordsInTheVocabulary) {
  const auto words = SyntheticBowWords(Frames({{0, 0, 0}, {3, 0, 0}}), appearance_, bow_, 7);
  ASSERT_EQ(words.size(), 2u);
  for (const auto& w : words) {
    EXPECT_EQ(w.size(), 300u);
    for (std::int32_t x : w) EXPECT_TRUE(x >= 0 && x < 10000) << x;
  }
}

TEST_F(SyntheticBowTest, DeterministicForASeed) {
  const Trajectory t = Frames({{0, 0, 0}, {50, 20, 1}});
  EXPECT_EQ(SyntheticBowWords(t, appearance_, bow_, 7), SyntheticBowWords(t, appearance_, bow_, 7));
  EXPECT_NE(SyntheticBowWords(t, appearance_, bow_, 7), SyntheticBowWords(t, appearance_, bow_, 8));
}

// Frame 0 and frame 1 (2 m further, same heading) see the same landmarks; frame 2 is 300 m away,
// frame 3 at frame 0's place looks the other way: they share only chance words.
TEST_F(SyntheticBowTest, RevisitsShareWordsOtherPlacesDoNot) {
  const auto w = SyntheticBowWords(Frames({{0, 0, 0}, {2, 0, 0}, {300, 0, 0}, {0, 0, std::numbers::pi}}),
                                   appearance_, bow_, 3);
  const std::size_t revisit = SharedWords(w[0], w[1]);
  EXPECT_GT(revisit, 50u);  // of about 200 distinct words per frame (300 features)
  EXPECT_LT(SharedWords(w[0], w[2]) * 10, revisit);
  EXPECT_LT(SharedWords(w[0], w[3]) * 10, revisit);
  const BowData data = TfIdfFromWords(w, bow_.vocabulary);
  EXPECT_GT(L1Score(data.frames[0], data.frames[1]), 5 * L1Score(data.frames[0], data.frames[2]));
}

TEST_F(SyntheticBowTest, AppearanceChangeLowersTheScoreOfALaterRevisit) {
  // The same place at frames 0, 1 (a frame later) and 2000 (ten appearance time scales later).
  SyntheticParams strong = appearance_;
  strong.appearance_change = 3.0;
  Trajectory later{Positions(2001, 3), Headings(2001, 3)};
  for (int i = 0; i < 2001; ++i) {
    later.positions.row(i) << 0, 1.5, 0;
    later.headings.row(i) << 1, 0, 0;
  }
  const BowData data = SyntheticBow(later, strong, bow_, 5);
  EXPECT_GT(L1Score(data.frames[0], data.frames[1]), L1Score(data.frames[0], data.frames[2000]));
}

TEST_F(SyntheticBowTest, ValidateNamesTheField) {
  bow_.vocabulary = 1;
  try {
    bow_.Validate();
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "vocabulary: must be in [2, 10000000], got 1");
  }
}

class BowFileTest : public ::testing::Test {
 protected:
  fs::path Text(const std::string& content) const {
    const fs::path dir = fs::path(DVPR_TEST_TMP) / "bow_file";
    fs::create_directories(dir);
    const fs::path p = dir / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".txt");
    std::ofstream(p, std::ios::binary) << content;
    return p;
  }
  void ExpectError(const std::string& content, std::initializer_list<std::string> needles) const {
    const fs::path p = Text(content);
    try {
      LoadBowFile(p);
      ADD_FAILURE() << "no exception for " << content;
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(p.string()), std::string::npos) << what;
      for (const auto& n : needles) EXPECT_NE(what.find(n), std::string::npos) << what;
    }
  }
};

// Line 1: 3:0.5 1:1.5 -> sorted {1: 1.5, 3: 0.5}, L1 norm 2 -> {1: 0.75, 3: 0.25};
// line 2: no words; line 3: {2: 4} -> {2: 1}. Vocabulary: largest word 3, + 1.
TEST_F(BowFileTest, ReadsSparseLines) {
  const BowData d = LoadBowFile(Text("3:0.5 1:1.5\n-\n\t2:4  \r\n"));
  EXPECT_EQ(d.vocabulary, 4);
  ASSERT_EQ(d.frames.size(), 3u);
  EXPECT_EQ(d.frames[0], (BowVector{{1, 0.75f}, {3, 0.25f}}));
  EXPECT_TRUE(d.frames[1].empty());
  EXPECT_EQ(d.frames[2], (BowVector{{2, 1.0f}}));
}

TEST_F(BowFileTest, TrailingBlankLinesAreNotFrames) {
  EXPECT_EQ(LoadBowFile(Text("1:1\n2:1\n\n\n")).frames.size(), 2u);
}

TEST_F(BowFileTest, MalformedLinesNameFileAndLine) {
  ExpectError("1:1\n2:abc\n", {"line 2", "'2:abc'", "weight"});
  ExpectError("1:1\n\n2:1\n", {"line 2", "empty line"});
  ExpectError("1:1 1:2\n", {"line 1", "word 1 appears twice"});
  ExpectError("-3:1\n", {"line 1", "whole number"});
  ExpectError("10000000:1\n", {"line 1", "[0, 10000000)"});
  ExpectError("5:0\n", {"line 1", "(0, 1e30]"});
  ExpectError("5:nan\n", {"line 1"});
  ExpectError("5\n", {"line 1", "WORD:WEIGHT"});
  ExpectError("", {"empty"});
}

// 1e-46 is positive as a double but below float32's smallest subnormal (2^-149, about 1.4e-45):
// it would be a word of weight 0. 1e-44 rounds to a float32 subnormal above 0 and is kept.
TEST_F(BowFileTest, AWeightThatIsZeroInFloat32IsRefused) {
  ExpectError("1:1 2:1e-46\n", {"line 1", "'2:1e-46'", "0 in float32"});
  EXPECT_EQ(LoadBowFile(Text("1:1e-44\n")).frames[0].size(), 1u);
}

TEST_F(BowFileTest, AFileWithoutASingleWordIsRefused) {
  ExpectError("-\n-\n", {"no frame has a word", "every line is '-'"});
}

// The binary triples (frame, word, weight), 12 bytes each, little-endian, in a .bin file.
class BowTriplesTest : public ::testing::Test {
 protected:
  struct T {
    std::int32_t frame, word;
    float weight;
  };
  static void Put32(std::string& out, std::uint32_t v) {
    for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((v >> (8 * b)) & 0xffu));
  }
  static std::string Bytes(std::initializer_list<T> triples) {
    std::string out;
    for (const T& t : triples) {
      Put32(out, static_cast<std::uint32_t>(t.frame));
      Put32(out, static_cast<std::uint32_t>(t.word));
      Put32(out, std::bit_cast<std::uint32_t>(t.weight));
    }
    return out;
  }
  fs::path Bin(const std::string& bytes) const {
    const fs::path dir = fs::path(DVPR_TEST_TMP) / "bow_triples";
    fs::create_directories(dir);
    const fs::path p = dir / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".bin");
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
  }
  void ExpectError(const std::string& bytes, std::initializer_list<std::string> needles) const {
    const fs::path p = Bin(bytes);
    try {
      LoadBowFile(p);
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(p.string()), std::string::npos) << what;
      for (const auto& n : needles) EXPECT_NE(what.find(n), std::string::npos) << what;
    }
  }
};

// One triple written out byte by byte: frame 1, word 3, weight 0.5f (IEEE 754: 0x3F000000).
// Frame 0 exists without words (frames run 0 .. largest), frame 1 is {3: 1} after L1.
TEST_F(BowTriplesTest, ReadsLittleEndianTriples) {
  const std::string bytes("\x01\x00\x00\x00\x03\x00\x00\x00\x00\x00\x00\x3f", 12);
  const BowData d = LoadBowFile(Bin(bytes));
  ASSERT_EQ(d.frames.size(), 2u);
  EXPECT_TRUE(d.frames[0].empty());
  EXPECT_EQ(d.frames[1], (BowVector{{3, 1.0f}}));
  EXPECT_EQ(d.vocabulary, 4);
}

// A binary file whose name ends in .BIN (any case) is read as triples too: it was read as text.
TEST_F(BowTriplesTest, AnUppercaseExtensionIsBinaryToo) {
  const fs::path lower = Bin(std::string("\x01\x00\x00\x00\x03\x00\x00\x00\x00\x00\x00\x3f", 12));
  const fs::path upper = lower.parent_path() / "BOW.BIN";
  fs::copy_file(lower, upper, fs::copy_options::overwrite_existing);
  const BowData d = LoadBowFile(upper);
  ASSERT_EQ(d.frames.size(), 2u);
  EXPECT_EQ(d.frames[1], (BowVector{{3, 1.0f}}));
}

// The text test's three frames as triples in a scrambled order give the same vectors:
// {1: 0.75, 3: 0.25}, {}, {2: 1}.
TEST_F(BowTriplesTest, SameVectorsAsTheTextFormatInAnyOrder) {
  const BowData d = LoadBowFile(Bin(Bytes({{0, 3, 0.5f}, {2, 2, 4.0f}, {0, 1, 1.5f}})));
  EXPECT_EQ(d.vocabulary, 4);
  ASSERT_EQ(d.frames.size(), 3u);
  EXPECT_EQ(d.frames[0], (BowVector{{1, 0.75f}, {3, 0.25f}}));
  EXPECT_TRUE(d.frames[1].empty());
  EXPECT_EQ(d.frames[2], (BowVector{{2, 1.0f}}));
}

// A weight of 0 adds no word; it only makes frame 3 exist, so the file has 4 frames.
TEST_F(BowTriplesTest, ZeroWeightDeclaresATrailingFrameWithoutWords) {
  const BowData d = LoadBowFile(Bin(Bytes({{0, 1, 2.0f}, {3, 9, 0.0f}})));
  ASSERT_EQ(d.frames.size(), 4u);
  EXPECT_EQ(d.frames[0], (BowVector{{1, 1.0f}}));
  EXPECT_TRUE(d.frames[3].empty());
  EXPECT_EQ(d.vocabulary, 2);
}

// Weights of 0 only declare frames: two frames, no word in either.
TEST_F(BowTriplesTest, AFileWithoutASingleWordIsRefused) {
  ExpectError(Bytes({{0, 1, 0.0f}, {1, 5, 0.0f}}), {"no frame has a word", "every weight is 0"});
}

TEST_F(BowTriplesTest, BadTriplesNameFileTripleAndByte) {
  ExpectError(Bytes({{0, 1, 1.0f}}) + "x", {"13 bytes", "12-byte"});
  ExpectError("", {"empty"});
  ExpectError(Bytes({{0, 1, 1.0f}, {-1, 1, 1.0f}}), {"triple 1 (byte 12)", "frame -1", "[0, 10000000)"});
  ExpectError(Bytes({{0, 10000000, 1.0f}}), {"triple 0 (byte 0)", "word 10000000"});
  ExpectError(Bytes({{0, 1, std::numeric_limits<float>::quiet_NaN()}}), {"triple 0", "weight", "[0, 1e30]"});
  ExpectError(Bytes({{0, 1, -1.0f}}), {"triple 0", "weight"});
  ExpectError(Bytes({{0, 1, 1.0f}, {1, 1, 1.0f}, {0, 1, 2.0f}}),
              {"triple 2 (byte 24)", "frame 0, word 1 appears twice", "first in triple 0"});
}

}  // namespace
}  // namespace dvpr
