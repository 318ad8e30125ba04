// The centroid files of a sweep (experiments/domain/strategies/run_centroids.h): each is checked for its
// count, width and values, and every error names the file, since a sweep reads many.
#include "experiments/domain/strategies/run_centroids.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "experiments/domain/data/npy.h"
#include "experiments/domain/strategies/run_placement.h"
#include "experiments/domain/strategies/strategy_spec.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

class CentroidFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("run_centroids");
    params_.centroids_pattern = (dir_ / "c_n{robots}_r{run}.npy").string();
  }
  // Writes the file of (robots, run): rows x cols, every value 0.5.
  fs::path Write(int robots, int run, Eigen::Index rows, Eigen::Index cols) {
    const fs::path p = ExpandCentroidPattern(params_.centroids_pattern, robots, run);
    WriteNpy(p, CentroidMatrix::Constant(rows, cols, 0.5f));
    return p;
  }
  // The message ReadCentroidFile's error carries, or "" when it does not throw.
  static std::string ErrorOf(const std::function<void()>& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
  RunCentroidParams params_;
};

TEST_F(CentroidFileTest, AFileOfTheRightShapeIsRead) {
  const fs::path p = Write(2, 0, 4, 3);
  const CentroidMatrix c = ReadCentroidFile(p, 2, 2, 3);
  EXPECT_EQ(c.rows(), 4);
  EXPECT_EQ(c.cols(), 3);
  EXPECT_EQ(c(3, 2), 0.5f);
}

TEST_F(CentroidFileTest, AWrongWidthNamesTheFileAndTheDescriptorWidth) {
  const fs::path p = Write(2, 0, 2, 16);
  EXPECT_EQ(ErrorOf([&] { ReadCentroidFile(p, 2, 1, 32); }),
            p.string() + ": 16 values per centroid, expected 32 (the descriptors' dataset.dim)");
}

TEST_F(CentroidFileTest, AWrongCountNamesTheFileAndTheTeam) {
  const fs::path p = Write(3, 0, 2, 4);
  EXPECT_EQ(ErrorOf([&] { ReadCentroidFile(p, 3, 2, 4); }),
            p.string() + ": 2 centroids, expected 6 (3 robots x 2 per robot)");
}

TEST_F(CentroidFileTest, ANonFiniteValueNamesTheFileAndTheRow) {
  CentroidMatrix c = CentroidMatrix::Constant(3, 2, 1.0f);
  c(2, 1) = std::numeric_limits<float>::quiet_NaN();
  const fs::path nan = dir_ / "nan.npy";
  WriteNpy(nan, c);
  EXPECT_EQ(ErrorOf([&] { ReadCentroidFile(nan, 3, 1, 2); }), nan.string() + ": centroid 2 (0-based row) holds NaN or Inf");
  c(2, 1) = 1.0f;
  c(1, 0) = -std::numeric_limits<float>::infinity();
  const fs::path inf = dir_ / "inf.npy";
  WriteNpy(inf, c);
  EXPECT_EQ(ErrorOf([&] { ReadCentroidFile(inf, 3, 1, 2); }), inf.string() + ": centroid 1 (0-based row) holds NaN or Inf");
}

// 2e9 squared over 4096 dimensions stays a float; a larger value might not (loaders.h).
TEST_F(CentroidFileTest, AValueBeyondTheDescriptorRangeNamesTheFileAndTheRow) {
  CentroidMatrix c = CentroidMatrix::Constant(2, 2, 1.0f);
  c(0, 1) = -2e9f;
  const fs::path p = dir_ / "big.npy";
  WriteNpy(p, c);
  EXPECT_EQ(ErrorOf([&] { ReadCentroidFile(p, 2, 1, 2); }),
            p.string() + ": centroid 0 (0-based row) holds a value outside [-1e9, 1e9]");
  c(0, 1) = -1e9f;  // the bound itself is allowed
  WriteNpy(p, c);
  EXPECT_EQ(ErrorOf([&] { ReadCentroidFile(p, 2, 1, 2); }), "");
}

// A sweep of robots {2, 3} x runs {0, 1} reads four files; the bad one is the last.
TEST_F(CentroidFileTest, CheckCentroidFilesReadsEveryRunOfTheSweep) {
  Write(2, 0, 2, 4);
  Write(2, 1, 2, 4);
  Write(3, 0, 3, 4);
  const fs::path last = Write(3, 1, 3, 5);
  EXPECT_EQ(ErrorOf([&] { CheckCentroidFiles(params_, {2, 3}, 2, 4); }),
            last.string() + ": 5 values per centroid, expected 4 (the descriptors' dataset.dim)");
  Write(3, 1, 3, 4);
  EXPECT_EQ(ErrorOf([&] { CheckCentroidFiles(params_, {2, 3}, 2, 4); }), "");
}

// With centroid files the training set has no rows but the descriptors' width, which the file
// must match (the run's own check, for callers that skip the sweep's: dvpr agent).
TEST_F(CentroidFileTest, RunCentroidsChecksTheFileAgainstTheTrainingWidth) {
  const fs::path p = Write(2, 0, 2, 16);
  EXPECT_EQ(ErrorOf([&] { RunCentroids(DescriptorMatrix(0, 32), params_, 2, 0); }),
            p.string() + ": 16 values per centroid, expected 32 (the descriptors' dataset.dim)");
  std::uint64_t seed = 99;
  EXPECT_EQ(RunCentroids(DescriptorMatrix(0, 16), params_, 2, 0, &seed).cols(), 16);
  EXPECT_EQ(seed, 0u);
}

// The sweep's cache (SharedInputs::centroid_cache): the runs of one (robots, run) - its
// strategies, the paper protocol and each sim network variant, on the sweep's threads - get one
// k-means (here: one read of the run's file, which is then deleted so that a second read fails).
TEST_F(CentroidFileTest, TheCacheComputesEachRunOnceForEveryThread) {
  Write(2, 0, 2, 4);
  RunCentroidCache cache;
  const DescriptorMatrix training(0, 4);
  constexpr int kThreads = 8;
  std::vector<const CentroidMatrix*> seen(kThreads, nullptr);
  {
    std::vector<std::jthread> threads;
    for (int i = 0; i < kThreads; ++i) {
      threads.emplace_back([&, i] { seen[i] = &cache.Get(training, params_, 2, 0); });
    }
  }
  for (const CentroidMatrix* c : seen) EXPECT_EQ(c, seen[0]);
  fs::remove_all(dir_);
  EXPECT_EQ(&cache.Get(training, params_, 2, 0), seen[0]);
  EXPECT_EQ(seen[0]->rows(), 2);
  // Clusters per robot is part of the key: 4 centroids for 2 robots are another file's.
  RunCentroidParams two_each = params_;
  two_each.clusters_per_robot = 2;
  EXPECT_THROW(cache.Get(training, two_each, 2, 0), std::runtime_error);
}

// A run whose k-means failed (its file is missing) is tried again by the next caller, and one
// cache serves one config's settings.
TEST_F(CentroidFileTest, TheCacheRetriesAFailedRunAndRefusesOtherSettings) {
  RunCentroidCache cache;
  const DescriptorMatrix training(0, 4);
  EXPECT_THROW(cache.Get(training, params_, 3, 1), std::runtime_error);
  Write(3, 1, 3, 4);
  EXPECT_EQ(cache.Get(training, params_, 3, 1).rows(), 3);
  RunCentroidParams other = params_;
  other.seed = 7;
  EXPECT_THROW(cache.Get(training, other, 3, 1), std::logic_error);
}

// Which strategies read the run's centroids and which the training descriptors themselves, per
// the table kinds of docs/strategies.md; C is the strategy's own or the config's (here 3).
TEST(TrainingUseTest, FollowsTheTable) {
  StrategyInputs in;
  in.centroids.clusters_per_robot = 3;
  const auto use = [&](const std::string& name) { return TrainingUseOf(ParseStrategy(name), in); };
  EXPECT_TRUE(use("decentralized").run_centroids);
  EXPECT_FALSE(use("decentralized").descriptors);
  EXPECT_EQ(use("decentralized").clusters_per_robot, 3);
  EXPECT_EQ(use("lpt_c10").clusters_per_robot, 10);
  EXPECT_TRUE(use("lpt_c10").run_centroids);
  EXPECT_FALSE(use("lpt_c10").descriptors);
  EXPECT_TRUE(use("lpt_c10_train").descriptors);
  EXPECT_TRUE(use("balanced_c4").descriptors);
  EXPECT_FALSE(use("balanced_c4").run_centroids);
  EXPECT_EQ(use("balanced_c4").clusters_per_robot, 4);
  EXPECT_FALSE(use("sample_c4").run_centroids || use("sample_c4").descriptors);
  EXPECT_FALSE(use("broadcast").run_centroids || use("broadcast").descriptors);
  EXPECT_EQ(use("broadcast").clusters_per_robot, 0);
}

}  // namespace
}  // namespace dvpr
