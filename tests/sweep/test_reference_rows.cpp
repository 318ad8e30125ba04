// The reference row of each protocol (the row the others' relative AUC divides by): its relative
// AUC is AUC / AUC = 1 when the run has something to recognise, and undefined (NaN, an empty
// cell) like every other row's when it has not: a prefix of KITTI 00 without a revisit has no
// relevant query, so every AUC is 0 and 0 / 0 is not 1. The paper, BoW and simulated reference
// rows used to disagree there (the static ones wrote 1).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/protocols/inputs.h"
#include "experiments/sweep/run_sweep.h"
#include "tests/kitti_every_tenth.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

class ReferenceRowsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("reference_rows");
    const Dataset data = testing_support::KittiEveryTenth(8, dir_ / "poses.txt");
    frames_ = static_cast<int>(data.size());
    // Words from the place: the 20 m grid cells (two grids, offset by 10 m) the frame lies in,
    // so a revisit shares words with the first visit.
    std::ofstream bow(dir_ / "bow.txt");
    const Positions& p = data.trajectory.positions;
    for (Eigen::Index i = 0; i < p.rows(); ++i) {
      const auto cell = [&](double offset) {
        const auto x = static_cast<long>(std::floor((p(i, 0) + offset) / 20));
        const auto z = static_cast<long>(std::floor((p(i, 2) + offset) / 20));
        return ((x * 7919 + z) % 500 + 500) % 500;
      };
      bow << cell(0) << ":1 " << 500 + cell(10) << ":1\n";
    }
  }
  // Every row of a 3-robot sweep over the first `frames` poses: both static protocols and the
  // simulation, the descriptors' and the BoW method's reference and decentralized strategies.
  std::vector<RunResult> Rows(int frames) const {
    const ExperimentConfig config = ParseConfig(
        "name: reference_rows\nseed: 3\n"
        "dataset: {source: synthetic, poses: poses.txt, bow: bow.txt, dim: 8, frames: " +
            std::to_string(frames) + "}\n"
            "training: {synthetic: {samples: 200}}\n"
            "robots: [3]\nruns: 1\nprotocols: [paper, sim]\n"
            "strategies: [decentralized, broadcast, bow_decentralized, bow_broadcast]\n"
            "network: {model: ideal}\nevaluation: {gt_radius_m: 5, suppression_frames: 25}\n"
            "outputs: {figures: false}\n",
        dir_, {}, "reference_rows.yaml");
    SharedInputs inputs = LoadSharedInputs(config, "reference_rows.yaml");
    inputs.out_dir = dir_ / "out";
    std::vector<RunResult> rows;
    for (const RunOutput& out : RunSweepInMemory(inputs, {.threads = 1, .progress = false})) {
      rows.insert(rows.end(), out.runs.begin(), out.runs.end());
    }
    return rows;
  }
  fs::path dir_;
  int frames_ = 0;
};

bool IsReference(const std::string& strategy) {
  return strategy == "broadcast" || strategy == "bow_broadcast";
}

// Every 10th KITTI 00 pose: the car is back at its start near pose 156, so 100 poses hold no
// revisit at all.
TEST_F(ReferenceRowsTest, WithoutARevisitNoRowHasARelativeAuc) {
  const std::vector<RunResult> rows = Rows(100);
  ASSERT_EQ(rows.size(), 8u);  // 2 protocols x 4 strategies
  for (const RunResult& row : rows) {
    SCOPED_TRACE(row.key.protocol + " " + row.key.strategy);
    EXPECT_EQ(row.auc, 0.0);
    EXPECT_EQ(row.auc_reference, 0.0);
    EXPECT_TRUE(std::isnan(row.relative_auc)) << row.relative_auc;
  }
}

TEST_F(ReferenceRowsTest, WithRevisitsTheReferenceRowsAreExactlyOne) {
  const std::vector<RunResult> rows = Rows(frames_);
  ASSERT_EQ(rows.size(), 8u);
  int references = 0;
  for (const RunResult& row : rows) {
    SCOPED_TRACE(row.key.protocol + " " + row.key.strategy);
    ASSERT_GT(row.auc_reference, 0.0);
    if (!IsReference(row.key.strategy)) continue;
    ++references;
    EXPECT_EQ(row.auc, row.auc_reference);
    EXPECT_EQ(row.relative_auc, 1.0);
  }
  EXPECT_EQ(references, 4);
}

}  // namespace
}  // namespace dvpr
