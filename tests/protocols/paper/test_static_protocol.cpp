// The paper's static protocol: exact restricted best matches, determinism, seeding, centroid
// files, and agreement with an independent numpy implementation (tests/tools/paper_eval.py).
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "sim/random_bits.h"
#include "experiments/data/npy.h"
#include "experiments/protocols/paper/static_protocol.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

DescriptorMatrix Uniform(int rows, int cols, std::uint64_t seed) {
  Xoshiro256 rng(seed);
  DescriptorMatrix x(rows, cols);
  for (int i = 0; i < x.size(); ++i) x.data()[i] = static_cast<float>(rng.Uniform() * 2 - 1);
  return x;
}

// Brute force in double: argmin over j outside the window with pool[j] == pool[i], ties lowest.
MatchOutcome BruteForce(const DescriptorMatrix& x, const std::vector<RobotId>& pool, int window,
                        int i) {
  MatchOutcome out{FrameId(i), std::nullopt, 0};
  for (int j = 0; j < x.rows(); ++j) {
    if (std::abs(i - j) <= window || pool[static_cast<std::size_t>(j)] != pool[static_cast<std::size_t>(i)]) continue;
    const double d = (x.row(i).cast<double>() - x.row(j).cast<double>()).squaredNorm();
    if (!out.match || d < out.score) out = {FrameId(i), FrameId(j), d};
  }
  return out;
}

TEST(WindowedNeighbours, EqualsBruteForceForAnyListSize) {
  DescriptorMatrix x = Uniform(150, 8, 1);
  for (int i = 100; i < 150; i += 7) x.row(i) = x.row(i - 90);  // exact ties in distance
  Xoshiro256 rng(2);
  std::vector<RobotId> pool;
  for (int i = 0; i < 150; ++i) pool.emplace_back(static_cast<int>(rng.Below(4)));
  pool[149] = RobotId(7);  // alone in its pool: no candidate
  for (int list_size : {1, 3, 200}) {
    const WindowedNeighbours nn(x, 5, list_size, 2);
    std::int64_t fallbacks = 0;
    const std::vector<MatchOutcome> got = nn.BestMatches(pool, &fallbacks);
    for (int i = 0; i < 150; ++i) {
      const MatchOutcome want = BruteForce(x, pool, 5, i);
      ASSERT_EQ(got[static_cast<std::size_t>(i)].match, want.match) << "list " << list_size << " query " << i;
      if (want.match) {
        EXPECT_NEAR(got[static_cast<std::size_t>(i)].score, want.score, 1e-12 * want.score);
      }
    }
    if (list_size == 1) {
      EXPECT_GT(fallbacks, 0);  // the fallback path was exercised
    }
    if (list_size == 200) {
      EXPECT_EQ(fallbacks, 0);
    }
  }
  EXPECT_FALSE(WindowedNeighbours(x, 5, 8, 1).BestMatches(pool)[149].match.has_value());
}

// A small deployment: every 10th pose of KITTI 00 (455 frames, revisits after ~1500 m) with
// random-but-smooth descriptors, sin(a_j . p / 20 m + b_j) plus 10% noise.
class PaperProtocolTest : public ::testing::Test {
 protected:
  static constexpr int kDim = 16;
  static constexpr int kWindow = 25;

  void SetUp() override {
    dir_ = fs::path(DVPR_TEST_TMP) / "static_protocol";
    fs::create_directories(dir_);
    std::ifstream in(DVPR_SOURCE_DIR "/data/kitti/00_poses.txt");
    std::ofstream poses(dir_ / "poses.txt");
    std::vector<double> xyz;
    int line_no = 0;
    for (std::string line; std::getline(in, line); ++line_no) {
      if (line_no % 10 != 0) continue;
      poses << line << "\n";
      std::istringstream row(line);
      double v[12];
      for (double& e : v) row >> e;
      xyz.insert(xyz.end(), {v[3], v[7], v[11]});
    }
    const auto n = static_cast<Eigen::Index>(xyz.size() / 3);
    data_.trajectory.positions = Eigen::Map<const Positions>(xyz.data(), n, 3);
    data_.trajectory.headings = Positions::Zero(n, 3);
    const DescriptorMatrix a = Uniform(kDim, 3, 3);
    const DescriptorMatrix b = Uniform(1, kDim, 4);
    const DescriptorMatrix noise = Uniform(static_cast<int>(n), kDim, 5);
    data_.descriptors.resize(n, kDim);
    for (Eigen::Index i = 0; i < n; ++i) {
      for (int j = 0; j < kDim; ++j) {
        const double phase = a.row(j).cast<double>().dot(data_.trajectory.positions.row(i)) / 20.0;
        data_.descriptors(i, j) = static_cast<float>(std::sin(phase + 3.0 * b(0, j)) + 0.1 * noise(i, j));
      }
    }
  }

  PaperProtocolParams Params() const {
    PaperProtocolParams p;
    p.evaluation = {.radius_m = 5, .suppression_frames = kWindow};
    p.robots = {2, 3, 5, 8};
    p.runs = 2;
    p.seed = 17;
    return p;
  }

  fs::path dir_;
  Dataset data_;
};

TEST_F(PaperProtocolTest, OneRobotReproducesTheCentralizedResult) {
  const PaperEvaluator evaluator(data_, {.radius_m = 5, .suppression_frames = kWindow}, 16, 1);
  EXPECT_EQ(evaluator.relevant(), 167);  // numpy on every 10th KITTI 00 pose, window 25
  const PaperRunResult r = evaluator.Evaluate(CentroidTable::RoundRobin(Uniform(3, kDim, 6), 1), true);
  EXPECT_EQ(r.row.auc, evaluator.centralized().auc);
  EXPECT_EQ(r.row.relative_auc, 1.0);
  EXPECT_EQ(r.row.worst_balance_ratio, 1.0);
  EXPECT_EQ(r.curve.precision, evaluator.centralized().precision);
  EXPECT_GT(evaluator.centralized().auc, 0.3);  // smooth descriptors: revisits are found
}

TEST_F(PaperProtocolTest, DeterministicForAnyThreadCountWithSeedsAndFiles) {
  const DescriptorMatrix training = Uniform(600, kDim, 7);
  PaperProtocolParams p = Params();
  p.threads = 1;
  p.centroids_out_dir = dir_ / "one_thread";
  const PaperProtocolResult one = RunPaperProtocol(data_, training, p);
  p.threads = 3;
  p.centroids_out_dir = dir_ / "three_threads";
  const PaperProtocolResult three = RunPaperProtocol(data_, training, p);
  ASSERT_EQ(one.runs.size(), 8u);
  for (std::size_t t = 0; t < one.runs.size(); ++t) {
    const PaperRunResult& a = one.runs[t];
    const PaperRunResult& b = three.runs[t];
    EXPECT_EQ(a.row.key.robots, p.robots[t / 2]);
    EXPECT_EQ(a.row.key.run, static_cast<int>(t % 2));
    EXPECT_EQ(a.row.seed, RunSeed(17, a.row.key.robots, a.row.key.run));
    EXPECT_EQ(a.row.auc, b.row.auc);
    EXPECT_EQ(a.row.worst_balance_ratio, b.row.worst_balance_ratio);
    ASSERT_EQ(a.centroids.size(), b.centroids.size());
    EXPECT_EQ(0, std::memcmp(a.centroids.data(), b.centroids.data(), sizeof(float) * a.centroids.size()));
    EXPECT_EQ(a.centroids_file.filename().string(), "centroids_n" + std::to_string(a.row.key.robots) +
                                                        "_r" + std::to_string(a.row.key.run) + ".npy");
    EXPECT_TRUE(ReadNpyMatrix(a.centroids_file) == a.centroids);
    EXPECT_EQ(a.row.queries, data_.size());
    EXPECT_EQ(a.per_robot.size(), static_cast<std::size_t>(a.row.key.robots));
  }
  EXPECT_NE(RunSeed(17, 2, 0), RunSeed(17, 2, 1));
  EXPECT_NE(RunSeed(17, 2, 0), RunSeed(17, 3, 0));
}

TEST(ExpandCentroidPattern, ReplacesEveryPlaceholder) {
  EXPECT_EQ(ExpandCentroidPattern("c/{robots}/n{robots}_r{run}.npy", 12, 3), fs::path("c/12/n12_r3.npy"));
}

TEST_F(PaperProtocolTest, GivenCentroidsWithTheWrongCountAreRejected) {
  WriteNpy(dir_ / "bad_n2_r0.npy", Uniform(3, kDim, 8));
  PaperProtocolParams p = Params();
  p.robots = {2};
  p.runs = 1;
  p.centroids_pattern = (dir_ / "bad_n{robots}_r{run}.npy").string();
  try {
    RunPaperProtocol(data_, DescriptorMatrix(), p);
    FAIL() << "3 centroids accepted for 2 robots";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bad_n2_r0.npy"), std::string::npos) << e.what();
  }
}

// dvpr and tests/tools/paper_eval.py on the same files: poses, descriptors, given centroids.
TEST_F(PaperProtocolTest, AgreesWithAnIndependentImplementation) {
  const fs::path desc = dir_ / "descriptors.npy";
  WriteNpy(desc, data_.descriptors);
  PaperProtocolParams p = Params();
  Xoshiro256 rng(9);
  for (int n : p.robots) {
    for (int run = 0; run < p.runs; ++run) {  // centroids near random frames: uneven routing
      CentroidMatrix c(n, kDim);
      for (int k = 0; k < n; ++k) {
        c.row(k) = data_.descriptors.row(static_cast<Eigen::Index>(rng.Below(static_cast<std::uint64_t>(data_.size()))));
      }
      c += 0.2f * Uniform(n, kDim, rng.Next());
      WriteNpy(ExpandCentroidPattern((dir_ / "given_n{robots}_r{run}.npy").string(), n, run), c);
    }
  }
  p.centroids_pattern = (dir_ / "given_n{robots}_r{run}.npy").string();
  const PaperProtocolResult ours = RunPaperProtocol(data_, DescriptorMatrix(), p);

  const fs::path out = dir_ / "reference.csv";
  fs::remove(out);
  const std::string cmd = "/usr/bin/python3 " DVPR_SOURCE_DIR "/tests/tools/paper_eval.py --poses '" +
                          (dir_ / "poses.txt").string() + "' --descriptors '" + desc.string() +
                          "' --centroids '" + p.centroids_pattern + "' --robots 2 3 5 8 --runs 2" +
                          " --radius 5 --window 25 --out '" + out.string() + "'";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::ifstream in(out);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  double central = 0;
  long relevant = 0;
  ASSERT_EQ(std::sscanf(line.c_str(), "centralized,%lf,%ld", &central, &relevant), 2) << line;
  EXPECT_EQ(relevant, 167);
  EXPECT_NEAR(ours.centralized.auc, central, 1e-4);
  double max_diff = std::abs(ours.centralized.auc - central);
  std::size_t rows = 0;
  for (; std::getline(in, line); ++rows) {
    int n = 0, run = 0;
    double auc = 0, rel = 0, wbr = 0;
    ASSERT_EQ(std::sscanf(line.c_str(), "%d,%d,%lf,%lf,%lf", &n, &run, &auc, &rel, &wbr), 5) << line;
    const PaperRunResult& r = ours.runs.at(rows);
    ASSERT_EQ(r.row.key.robots, n);
    ASSERT_EQ(r.row.key.run, run);
    EXPECT_NEAR(r.row.auc, auc, 1e-4) << "n " << n << " run " << run;
    EXPECT_NEAR(r.row.relative_auc, rel, 1e-4) << "n " << n << " run " << run;
    EXPECT_DOUBLE_EQ(r.row.worst_balance_ratio, wbr) << "n " << n << " run " << run;
    max_diff = std::max(max_diff, std::abs(r.row.auc - auc));
  }
  EXPECT_EQ(rows, ours.runs.size());
  std::cout << "max |AUC(dvpr) - AUC(paper_eval.py)| = " << max_diff << "\n";
}

}  // namespace
}  // namespace dvpr
