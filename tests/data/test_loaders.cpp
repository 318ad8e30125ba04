#include "experiments/domain/data/loaders.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "experiments/domain/data/npy.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

class LoadersTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("loaders");
  }
  fs::path Text(const std::string& name, const std::string& content) const {
    std::ofstream(dir_ / name, std::ios::binary) << content;
    return dir_ / name;
  }
  fs::path Bin(const std::string& name, const std::vector<float>& values) const {
    std::ofstream out(dir_ / name, std::ios::binary);
    out.write(reinterpret_cast<const char*>(values.data()),
              static_cast<std::streamsize>(values.size() * sizeof(float)));
    return dir_ / name;
  }
  fs::path Npy(const std::string& name, const DescriptorMatrix& m) const {
    WriteNpy(dir_ / name, m);
    return dir_ / name;
  }
  // `n` KITTI pose lines: identity rotation, position (i, 0, 2i).
  static std::string Poses(int n) {
    std::string s;
    for (int i = 0; i < n; ++i) {
      s += "1 0 0 " + std::to_string(i) + " 0 1 0 0 0 0 1 " + std::to_string(2 * i) + "\n";
    }
    return s;
  }
  static void ExpectError(const std::function<void()>& f, std::initializer_list<std::string> needles) {
    try {
      f();
      ADD_FAILURE() << "no exception";
    } catch (const std::exception& e) {
      const std::string what = e.what();
      for (const auto& n : needles) EXPECT_NE(what.find(n), std::string::npos) << what;
    }
  }
  fs::path dir_;
};

TEST_F(LoadersTest, LoadsShippedKitti00) {
  const Trajectory t = LoadKittiPoses(fs::path(DVPR_SOURCE_DIR) / "data/kitti/00_poses.txt");
  ASSERT_EQ(t.size(), 4541);
  // Line 2: ... -4.690294e-02 ... -2.839928e-02 ... 8.586941e-01, heading column ~ (0.002, 0.001, 1).
  EXPECT_DOUBLE_EQ(t.positions(1, 0), -4.690294e-02);
  EXPECT_DOUBLE_EQ(t.positions(1, 1), -2.839928e-02);
  EXPECT_DOUBLE_EQ(t.positions(1, 2), 8.586941e-01);
  EXPECT_NEAR(t.headings(1, 0), -2.066935e-03, 1e-8);
  EXPECT_NEAR(t.headings(1, 2), 1.0, 1e-5);
  for (Eigen::Index i = 0; i < t.size(); ++i) ASSERT_NEAR(t.headings.row(i).norm(), 1.0, 1e-12);
}

TEST_F(LoadersTest, KittiAcceptsCrlfAndTrailingBlankLines) {
  const Trajectory t = LoadKittiPoses(Text("p.txt", "1 0 0 5 0 1 0 6 0 0 2 7\r\n\n  \n"));
  ASSERT_EQ(t.size(), 1);
  EXPECT_EQ(t.positions.row(0), Eigen::RowVector3d(5, 6, 7));
  EXPECT_EQ(t.headings.row(0), Eigen::RowVector3d(0, 0, 1));  // normalised from (0, 0, 2)
}

// Found by tests/fuzz/fuzz_poses: squaring (3e200, 0, 4e200) overflows, and the heading came out
// (0, 0, 0) instead of (0.6, 0, 0.8).
TEST_F(LoadersTest, KittiNormalisesHugeHeadingColumns) {
  const Trajectory t = LoadKittiPoses(Text("p.txt", "1 0 3e200 0 0 1 0 0 0 0 4e200 0\n"));
  ASSERT_EQ(t.size(), 1);
  EXPECT_NEAR(t.headings(0, 0), 0.6, 1e-15);
  EXPECT_EQ(t.headings(0, 1), 0.0);
  EXPECT_NEAR(t.headings(0, 2), 0.8, 1e-15);
  // At the top of the double range: (1.5e308, 1.5e308, 1.5e308) / its norm = 1/sqrt(3) each.
  const Trajectory top = LoadKittiPoses(Text("q.txt", "1 0 1.5e308 0 0 1 1.5e308 0 0 0 1.5e308 0\n"));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(top.headings(0, k), 0.5773502691896258, 1e-15);
}

TEST_F(LoadersTest, KittiErrorsNameFileAndLine) {
  ExpectError([&] { LoadKittiPoses(Text("count.txt", Poses(1) + "1 2 3 4 5 6 7 8 9 10 11\n")); },
              {"count.txt", "line 2", "expected 12", "got 11"});
  ExpectError([&] { LoadKittiPoses(Text("word.txt", Poses(2) + "1 0 0 x 0 1 0 0 0 0 1 0\n")); },
              {"word.txt", "line 3", "not a number: 'x'"});
  ExpectError([&] { LoadKittiPoses(Text("nan.txt", "1 0 0 nan 0 1 0 0 0 0 1 0\n")); },
              {"nan.txt", "line 1", "NaN or Inf"});
  ExpectError([&] { LoadKittiPoses(Text("inf.txt", Poses(3) + "1 0 0 0 0 1 0 -inf 0 0 1 0\n")); },
              {"line 4", "NaN or Inf"});
  ExpectError([&] { LoadKittiPoses(Text("empty.txt", "\n\n")); }, {"empty.txt", "empty"});
  ExpectError([&] { LoadKittiPoses(Text("gap.txt", Poses(1) + "\n" + Poses(1))); },
              {"gap.txt", "line 2", "empty line"});
  ExpectError([&] { LoadKittiPoses(Text("zero.txt", "1 0 0 0 0 1 0 0 0 0 0 0\n")); },
              {"line 1", "heading"});
  ExpectError([&] { LoadKittiPoses(dir_ / "missing.txt"); }, {"missing.txt", "cannot open"});
}

TEST_F(LoadersTest, NpyKeepsFirstDimColumns) {
  const fs::path f = fs::path(DVPR_SOURCE_DIR) / "tests/data/fixtures/f8_f.npy";
  const DescriptorMatrix m = LoadDescriptors(f, 2);
  ASSERT_EQ(m.rows(), 3);
  ASSERT_EQ(m.cols(), 2);
  EXPECT_EQ(m(2, 1), 4.5f - 1.0f + 0.5f * 0);  // value 9 * 0.5 - 1 = 3.5 at (2, 1)
}

TEST_F(LoadersTest, NpyErrors) {
  const fs::path f = fs::path(DVPR_SOURCE_DIR) / "tests/data/fixtures/f4_c.npy";
  ExpectError([&] { LoadDescriptors(f, 5); }, {"f4_c.npy", "dim 5", "4 values per frame"});
  ExpectError([&] { LoadDescriptors(f, 0); }, {"dim must be positive"});
  ExpectError([] { LoadDescriptors(fs::path(DVPR_SOURCE_DIR) / "tests/data/fixtures/int32.npy", 2); },
              {"int32.npy", "dtype"});
  ExpectError([] { LoadDescriptors(fs::path(DVPR_SOURCE_DIR) / "tests/data/fixtures/truncated.npy", 2); },
              {"truncated"});
  ExpectError([] { LoadDescriptors(fs::path(DVPR_SOURCE_DIR) / "tests/data/fixtures/empty_f4.npy", 2); },
              {"no frames"});
  DescriptorMatrix m = DescriptorMatrix::Ones(4, 3);
  m(2, 1) = std::numeric_limits<float>::quiet_NaN();
  ExpectError([&] { LoadDescriptors(Npy("nan.npy", m), 3); }, {"nan.npy", "frame 2", "NaN or Inf"});
  m(2, 1) = 1.0f;
  m.row(3) << 0.0f, 0.0f, 7.0f;  // zero within the kept columns is what counts
  EXPECT_NO_THROW(LoadDescriptors(Npy("ok.npy", m), 3));
  ExpectError([&] { LoadDescriptors(Npy("zero.npy", m), 2); }, {"zero.npy", "frame 3", "all-zero"});
}

TEST_F(LoadersTest, BinReadsFramesBackToBack) {
  std::vector<float> v(3 * 6);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<float>(i + 1);
  const DescriptorMatrix m = LoadDescriptors(Bin("d.bin", v), 4, 6);
  ASSERT_EQ(m.rows(), 3);
  ASSERT_EQ(m.cols(), 4);
  EXPECT_EQ(m.row(1), Eigen::RowVector4f(7, 8, 9, 10));
  EXPECT_EQ(m(2, 3), 16.0f);
}

TEST_F(LoadersTest, BinErrors) {
  std::vector<float> v(2 * 6, 1.0f);
  v.push_back(1.0f);  // 13 values: not a whole number of 6-value frames
  ExpectError([&] { LoadDescriptors(Bin("trunc.bin", v), 4, 6); },
              {"trunc.bin", "52 bytes", "not a multiple", "6 float32"});
  v.pop_back();
  ExpectError([&] { LoadDescriptors(Bin("wide.bin", v), 7, 6); }, {"dim 7", "6 values per frame"});
  ExpectError([&] { LoadDescriptors(Bin("w0.bin", v), 4, 0); }, {"bin_frame_width"});
  ExpectError([&] { LoadDescriptors(Bin("none.bin", {}), 4, 6); }, {"none.bin", "no frames"});
  v[6 + 2] = std::numeric_limits<float>::infinity();
  ExpectError([&] { LoadDescriptors(Bin("inf.bin", v), 4, 6); }, {"inf.bin", "frame 1", "NaN or Inf"});
  std::fill(v.begin(), v.begin() + 6, 0.0f);
  ExpectError([&] { LoadDescriptors(Bin("zero.bin", v), 4, 6); }, {"frame 0", "all-zero"});
}

TEST_F(LoadersTest, CsvReadsRows) {
  const DescriptorMatrix m = LoadDescriptors(Text("d.csv", "1, 2,3\n4,5 ,6e1\r\n-7,+8,9\n"), 3);
  ASSERT_EQ(m.rows(), 3);
  EXPECT_EQ(m.row(1), Eigen::RowVector3f(4, 5, 60));
  EXPECT_EQ(m.row(2), Eigen::RowVector3f(-7, 8, 9));
  EXPECT_EQ(LoadDescriptors(Text("d2.csv", "1,2,3\n"), 1).cols(), 1);
}

TEST_F(LoadersTest, CsvErrorsNameLine) {
  ExpectError([&] { LoadDescriptors(Text("short.csv", "1,2,3\n4,5\n"), 2); },
              {"short.csv", "line 2", "expected 3 values", "got 2"});
  ExpectError([&] { LoadDescriptors(Text("word.csv", "1,2\n3,4\n5,abc\n"), 2); },
              {"line 3", "not a number: 'abc'"});
  ExpectError([&] { LoadDescriptors(Text("blank.csv", "1,2\n3,,4\n"), 1); }, {"line 2"});
  ExpectError([&] { LoadDescriptors(Text("nan.csv", "1,2\nNaN,1\n"), 2); }, {"line 2", "NaN or Inf"});
  ExpectError([&] { LoadDescriptors(Text("dim.csv", "1,2\n"), 3); }, {"dim 3", "2 values per frame"});
  ExpectError([&] { LoadDescriptors(Text("zero.csv", "1,2\n0,0\n"), 2); }, {"frame 1", "all-zero"});
  ExpectError([&] { LoadDescriptors(Text("empty.csv", ""), 2); }, {"empty.csv", "empty"});
  ExpectError([&] { LoadDescriptors(Text("d.txt", "1,2\n"), 2); }, {"unknown", "'.txt'"});
}

TEST_F(LoadersTest, DatasetChecksFrameCounts) {
  DatasetFiles files;
  files.name = "toy";
  files.poses = Text("p.txt", Poses(4));
  files.descriptors = Text("d.csv", "1,0\n2,0\n3,0\n4,0\n");
  files.dim = 2;
  const Dataset d = LoadDataset(files);
  EXPECT_EQ(d.name, "toy");
  EXPECT_EQ(d.size(), 4);
  EXPECT_EQ(d.trajectory.positions.row(3), Eigen::RowVector3d(3, 0, 6));

  files.frames = 2;
  const Dataset first = LoadDataset(files);
  EXPECT_EQ(first.size(), 2);
  EXPECT_EQ(first.trajectory.size(), 2);
  files.frames = 5;
  ExpectError([&] { LoadDataset(files); }, {"dataset.frames", "5", "only 4"});

  files.frames = -1;
  files.descriptors = Text("d3.csv", "1,0\n2,0\n3,0\n");
  ExpectError([&] { LoadDataset(files); }, {"mismatch", "p.txt", "has 4 frames", "d3.csv", "has 3"});
}

TEST_F(LoadersTest, DatasetFilesValidateNamesField) {
  DatasetFiles ok;
  ok.poses = "p.txt";
  ok.descriptors = "d.npy";
  EXPECT_NO_THROW(ok.Validate());
  DatasetFiles f = ok;
  f.dim = 0;
  ExpectError([&] { f.Validate(); }, {"dataset.dim"});
  f = ok;
  f.frames = 0;
  ExpectError([&] { f.Validate(); }, {"dataset.frames"});
  f = ok;
  f.poses.clear();
  ExpectError([&] { f.Validate(); }, {"dataset.poses"});
  f = ok;
  f.fps = 0;
  ExpectError([&] { f.Validate(); }, {"dataset.fps"});
}

// Asked for more frames than the pose file has, the error says so (a shorter run than asked for
// would otherwise look like the one the config describes).
TEST_F(LoadersTest, KeepFirstFramesRefusesMoreFramesThanThePoseFileHas) {
  const fs::path poses = Text("p.txt", Poses(4));
  Trajectory t = LoadKittiPoses(poses);
  try {
    KeepFirstFrames(t, 5, poses);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "5 frames requested, but the pose file " + poses.string() + " has only 4");
  }
  KeepFirstFrames(t, 4, poses);
  EXPECT_EQ(t.size(), 4);
  KeepFirstFrames(t, -1, poses);  // all
  EXPECT_EQ(t.size(), 4);
  KeepFirstFrames(t, 2, poses);
  EXPECT_EQ(t.size(), 2);
  EXPECT_EQ(t.positions.row(1), Eigen::RowVector3d(1, 0, 2));
  EXPECT_EQ(t.headings.rows(), 2);
}

TEST_F(LoadersTest, SameFrameCountNamesBothFiles) {
  const Trajectory t = LoadKittiPoses(Text("p.txt", Poses(3)));
  const DescriptorMatrix d = DescriptorMatrix::Ones(2, 4);
  try {
    CheckSameFrameCount(t, "p.txt", d, "d.npy");
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "frame count mismatch: pose file p.txt has 3 frames, descriptor file d.npy has 2");
  }
  EXPECT_NO_THROW(CheckSameFrameCount(t, "p.txt", DescriptorMatrix::Ones(3, 4), "d.npy"));
}

// A token is quoted escaped: a carriage return or control byte inside it stays on the one line.
TEST_F(LoadersTest, ANonNumberIsQuotedOnOneLine) {
  const fs::path p = Text("cr.csv", std::string("1,2\r3,4\n", 8));
  try {
    LoadDescriptors(p, 3);
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), p.string() + ": line 1: not a number: '2\\r3'");
  }
}

// Positions beyond 1e9 m and descriptor values beyond 1e9 would overflow squared distances or the
// metrics' grid cells (loaders.h); the bound itself is allowed.
TEST_F(LoadersTest, ValuesBeyondTheDocumentedRangesAreRefused) {
  const fs::path far = Text("far.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1e300 0 1 0 0 0 0 1 0\n");
  ExpectError([&] { LoadKittiPoses(far); }, {"far.txt: line 2: translation 1e300 m is outside [-1e9, 1e9] m"});
  const fs::path edge = Text("edge.txt", "1 0 0 -1e9 0 1 0 1e9 0 0 1 0\n");
  EXPECT_EQ(LoadKittiPoses(edge).positions.row(0), Eigen::RowVector3d(-1e9, 1e9, 0));
  const fs::path big = Text("big.csv", "1,2\n3,-2e9\n");
  ExpectError([&] { LoadDescriptors(big, 2); }, {"big.csv: frame 1 (0-based row) holds a value outside [-1e9, 1e9]"});
  // A rotation column of 1e200 is scaled before it is normalised (the fuzz-found fix), so it
  // loads as the unit heading (1, 1, 1) / sqrt(3) rather than overflowing.
  const fs::path tilt = Text("tilt.txt", "1 0 1e200 0 0 1 1e200 0 0 0 1e200 0\n");
  const Eigen::RowVector3d heading = LoadKittiPoses(tilt).headings.row(0);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(heading[k], 1.0 / std::sqrt(3.0), 1e-15);
}

}  // namespace
}  // namespace dvpr
