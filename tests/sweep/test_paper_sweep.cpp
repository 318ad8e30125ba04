// The paper protocol's sweep driven as `dvpr run` drives it (RunSweep with the built-in
// protocols, from a config through LoadSharedInputs): determinism for any thread count, run
// seeds, centroid files, errors naming the run, and agreement with an independent numpy
// implementation of the paper's evaluation (tests/tools/paper_eval.py), read from runs.csv as written.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/domain/data/npy.h"
#include "experiments/protocols/inputs.h"
#include "experiments/results/result_writers.h"
#include "experiments/sweep/run_sweep.h"
#include "sim/random_bits.h"
#include "tests/kitti_every_tenth.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

using testing_support::Slurp;
using testing_support::UniformMatrix;

// The auc, auc_reference and relative_auc columns of a runs.csv, read with strtod from the
// text (not through dvpr's own reader), by the header's column names.
struct CsvAucs {
  int robots = 0;
  int run = 0;
  double auc = 0;
  double auc_reference = 0;
  double relative_auc = 0;
};

std::vector<std::string> Fields(const std::string& line) {
  std::vector<std::string> fields(1);
  for (char ch : line) {
    if (ch == ',') fields.emplace_back();
    else fields.back() += ch;
  }
  return fields;
}

std::vector<CsvAucs> ReadAucColumns(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = Fields(line);
  auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const std::size_t robots = column("robots"), run = column("run"), auc = column("auc"),
                    reference = column("auc_reference"), relative = column("relative_auc");
  std::vector<CsvAucs> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> f = Fields(line);
    rows.push_back({std::stoi(f.at(robots)), std::stoi(f.at(run)), std::strtod(f.at(auc).c_str(), nullptr),
                    std::strtod(f.at(reference).c_str(), nullptr), std::strtod(f.at(relative).c_str(), nullptr)});
  }
  return rows;
}

// Every 10th KITTI 00 pose with smooth 16-D descriptors (tests/kitti_every_tenth.h), written to
// files that a config names, as a user's own data would be.
class PaperSweepTest : public ::testing::Test {
 protected:
  static constexpr int kDim = 16;
  static constexpr int kRobots[4] = {2, 3, 5, 8};

  void SetUp() override {
    // One folder per test: ctest runs the tests of this binary in parallel processes.
    dir_ = dvpr::testing_support::FreshTestDir("paper_sweep");
    data_ = testing_support::KittiEveryTenth(kDim, dir_ / "poses.txt");
    WriteNpy(dir_ / "descriptors.npy", data_.descriptors);
  }

  // Seed 17, robots 2 3 5 8, 2 runs, the paper protocol's decentralized strategy, r = 5 m,
  // window 25; `training` is the config's training section.
  ExperimentConfig Config(const std::string& training, const std::vector<ConfigOverride>& overrides = {}) const {
    return ParseConfig("name: paper_sweep\nseed: 17\n"
                       "dataset: {source: files, poses: poses.txt, descriptors: descriptors.npy, dim: 16}\n" +
                           training +
                           "robots: [2, 3, 5, 8]\nruns: 2\nprotocols: [paper]\nstrategies: [decentralized]\n"
                           "evaluation: {gt_radius_m: 5, suppression_frames: 25}\noutputs: {figures: false}\n",
                       dir_, overrides, "paper_sweep.yaml");
  }

  // The sweep as dvpr run runs it, outputs in memory; trained centroids go to out_dir/centroids.
  static std::vector<RunOutput> Run(const ExperimentConfig& config, int threads, const fs::path& out_dir) {
    SharedInputs inputs = LoadSharedInputs(config, "paper_sweep.yaml");
    inputs.out_dir = out_dir;
    return RunSweepInMemory(inputs, {.threads = threads, .progress = false});
  }

  fs::path dir_;
  Dataset data_;
};

TEST_F(PaperSweepTest, DeterministicForAnyThreadCountWithSeedsAndCentroidFiles) {
  WriteNpy(dir_ / "training.npy", UniformMatrix(600, kDim, 7));
  const ExperimentConfig config = Config("training: {source: files, descriptors: training.npy}\n");
  const std::vector<RunOutput> one = Run(config, 1, dir_ / "one_thread");
  const std::vector<RunOutput> three = Run(config, 3, dir_ / "three_threads");
  // RunSeed(17, robots, run), by tests/tools/run_seeds.py 17 2 3 5 8 --runs 2 (a Python SplitMix64).
  const std::uint64_t seeds[8] = {1116627968581454675ULL,  13162643996549390066ULL, 13443829744536706695ULL,
                                  3091820598564804340ULL,  15872811474034375415ULL, 3296143284983473276ULL,
                                  16560372444893198574ULL, 5996917089926101225ULL};
  ASSERT_EQ(one.size(), 8u);
  ASSERT_EQ(three.size(), 8u);
  for (std::size_t t = 0; t < one.size(); ++t) {
    const int n = kRobots[t / 2];
    const int run = static_cast<int>(t % 2);
    ASSERT_EQ(one[t].runs.size(), 1u);
    const RunResult& row = one[t].runs[0];
    EXPECT_EQ(row.key.protocol, "paper");
    EXPECT_EQ(row.key.strategy, "decentralized");
    EXPECT_EQ(row.key.robots, n);
    EXPECT_EQ(row.key.run, run);
    EXPECT_EQ(row.seed, seeds[t]) << "n=" << n << " run " << run;
    EXPECT_EQ(row.queries, data_.size());
    EXPECT_EQ(CsvRow(row), CsvRow(three[t].runs.at(0)));
    ASSERT_EQ(one[t].per_robot.size(), static_cast<std::size_t>(n));
    std::int64_t routed = 0;
    for (std::size_t r = 0; r < one[t].per_robot.size(); ++r) {
      routed += one[t].per_robot[r].queries_received;
      EXPECT_EQ(CsvRow(one[t].per_robot[r]), CsvRow(three[t].per_robot.at(r)));
    }
    EXPECT_EQ(routed, data_.size());  // every frame is routed to exactly one robot
    const std::string name = "centroids_n" + std::to_string(n) + "_r" + std::to_string(run) + ".npy";
    const fs::path a = dir_ / "one_thread/centroids" / name;
    const DescriptorMatrix centroids = ReadNpyMatrix(a);
    EXPECT_EQ(centroids.rows(), n);  // k = n x 1 cluster per robot
    EXPECT_EQ(centroids.cols(), kDim);
    EXPECT_EQ(Slurp(a), Slurp(dir_ / "three_threads/centroids" / name)) << name;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "one_thread/centroids"), fs::directory_iterator()), 8);
}

TEST_F(PaperSweepTest, GivenCentroidsWithTheWrongCountAreRejectedNamingTheRunAndFile) {
  WriteNpy(dir_ / "bad_n2_r0.npy", UniformMatrix(3, kDim, 8));
  const ExperimentConfig config =
      Config("training: {centroids: 'bad_n{robots}_r{run}.npy'}\n", {{"robots", "[2]"}, {"runs", "1"}});
  try {
    Run(config, 1, dir_ / "bad");
    FAIL() << "3 centroids accepted for 2 robots";
  } catch (const std::exception& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("run paper n=2 run 0: ", 0), 0u) << what;
    EXPECT_NE(what.find("bad_n2_r0.npy"), std::string::npos) << what;
  }
}

// dvpr and tests/tools/paper_eval.py on the same files: poses, descriptors, given centroids.
TEST_F(PaperSweepTest, AgreesWithAnIndependentImplementation) {
  Xoshiro256 rng(9);
  for (int n : kRobots) {
    for (int run = 0; run < 2; ++run) {  // centroids near random frames: uneven routing
      CentroidMatrix c(n, kDim);
      for (int k = 0; k < n; ++k) {
        c.row(k) = data_.descriptors.row(static_cast<Eigen::Index>(rng.Below(static_cast<std::uint64_t>(data_.size()))));
      }
      c += 0.2f * UniformMatrix(n, kDim, rng.Next());
      WriteNpy(dir_ / ("given_n" + std::to_string(n) + "_r" + std::to_string(run) + ".npy"), c);
    }
  }
  const std::vector<RunOutput> ours = Run(Config("training: {centroids: 'given_n{robots}_r{run}.npy'}\n"), 0, dir_ / "given");
  // runs.csv as `dvpr run` writes it (the same header and CsvRow), read back as text below:
  // what is compared is what a user's script would read, not only the in-process doubles.
  std::vector<RunResult> written;
  for (const RunOutput& o : ours) written.insert(written.end(), o.runs.begin(), o.runs.end());
  WriteRunsCsv(dir_ / "runs.csv", written);
  const std::vector<CsvAucs> csv = ReadAucColumns(dir_ / "runs.csv");
  ASSERT_EQ(csv.size(), written.size());

  const fs::path out = dir_ / "reference.csv";
  const std::vector<std::string> argv{"/usr/bin/python3", DVPR_SOURCE_DIR "/tests/tools/paper_eval.py",
                                      "--poses", (dir_ / "poses.txt").string(),
                                      "--descriptors", (dir_ / "descriptors.npy").string(),
                                      "--centroids", (dir_ / "given_n{robots}_r{run}.npy").string(),
                                      "--robots", "2", "3", "5", "8", "--runs", "2", "--radius", "5", "--window", "25",
                                      "--out", out.string()};
  const fs::path log = dir_ / "paper_eval.log";
  ASSERT_EQ(testing_support::RunProgram(argv, log), 0) << testing_support::Slurp(log);
  std::ifstream in(out);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  double central = 0;
  long relevant = 0;
  ASSERT_EQ(std::sscanf(line.c_str(), "centralized,%lf,%ld", &central, &relevant), 2) << line;
  EXPECT_EQ(relevant, 167);
  ASSERT_EQ(ours.size(), 8u);
  // Both sides compute in double: they agree to rounding, far below the old 6 printed decimals.
  constexpr double kTolerance = 1e-12;
  EXPECT_NEAR(ours[0].runs.at(0).auc_reference, central, kTolerance);
  double max_diff = std::abs(ours[0].runs.at(0).auc_reference - central);
  std::size_t rows = 0;
  for (; std::getline(in, line); ++rows) {
    int n = 0, run = 0;
    double auc = 0, rel = 0, wbr = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%d,%d,%lf,%lf,%lf", &n, &run, &auc, &rel, &wbr), 5) << line;
    ASSERT_EQ(ours.at(rows).runs.size(), 1u);
    const RunResult& r = ours[rows].runs[0];
    ASSERT_EQ(r.key.robots, n);
    ASSERT_EQ(r.key.run, run);
    EXPECT_EQ(r.seed, 0u);  // given centroids: no k-means
    EXPECT_NEAR(r.auc, auc, kTolerance) << "n " << n << " run " << run;
    EXPECT_NEAR(r.relative_auc, rel, kTolerance) << "n " << n << " run " << run;
    EXPECT_DOUBLE_EQ(r.worst_balance_ratio, wbr) << "n " << n << " run " << run;
    const CsvAucs& c = csv.at(rows);
    ASSERT_EQ(c.robots, n);
    ASSERT_EQ(c.run, run);
    EXPECT_NEAR(c.auc, auc, kTolerance) << "runs.csv, n " << n << " run " << run;
    EXPECT_NEAR(c.auc_reference, central, kTolerance) << "runs.csv, n " << n << " run " << run;
    EXPECT_NEAR(c.relative_auc, rel, kTolerance) << "runs.csv, n " << n << " run " << run;
    EXPECT_EQ(c.auc, r.auc) << "runs.csv does not read back to the computed double";
    max_diff = std::max({max_diff, std::abs(r.auc - auc), std::abs(c.auc - auc),
                         std::abs(c.auc_reference - central)});
  }
  EXPECT_EQ(rows, ours.size());
  std::cout << "max |AUC(dvpr runs.csv) - AUC(paper_eval.py)| = " << max_diff << "\n";
}

}  // namespace
}  // namespace dvpr
