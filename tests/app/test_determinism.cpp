// The same config and seed give the same output files, byte for byte, whatever
// the thread count; another seed gives other results (docs/design.md: reproducible runs).
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/test_support.h"

namespace {

using dvpr::testing_support::RunProgram;
using dvpr::testing_support::Slurp;

namespace fs = std::filesystem;

class DeterminismTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = dvpr::testing_support::FreshTestDir("determinism");
  }
  // A small sweep: 900 frames of KITTI 00 (a revisit inside), both protocols and
  // strategies, two network models, every optional output except figures.
  fs::path Run(const std::string& name, const std::vector<std::string>& extra) {
    const fs::path out = dir_ / name;
    std::vector<std::string> argv{std::string(DVPR_BINARY_DIR) + "/dvpr", "run",
                                  std::string(DVPR_SOURCE_DIR) + "/experiments/configs/paper_kitti00.yaml",
                                  "--quiet", "--out", out.string()};
    for (const char* set : {"dataset.frames=900", "evaluation.suppression_frames=50", "robots=[2,4]", "runs=1",
                            "training.synthetic.samples=2000", "outputs.figures=false", "outputs.queries=true",
                            "outputs.messages=true", "outputs.lcm_log=true"}) {
      argv.insert(argv.end(), {"--set", set});
    }
    argv.insert(argv.end(), extra.begin(), extra.end());
    const int status = RunProgram(argv, dir_ / (name + ".log"));
    EXPECT_EQ(status, 0) << Slurp(dir_ / (name + ".log"));
    return out;
  }
  fs::path dir_;
};

TEST_F(DeterminismTest, SameSeedSameBytesOtherSeedOtherResults) {
  const fs::path a = Run("a", {"--threads", "1"});
  const fs::path b = Run("b", {"--threads", "2"});
  const fs::path c = Run("c", {"--set", "seed=2"});
  int compared = 0;
  for (const auto& entry : fs::recursive_directory_iterator(a)) {
    if (!entry.is_regular_file()) continue;
    const fs::path rel = fs::relative(entry.path(), a);
    ASSERT_TRUE(fs::exists(b / rel)) << rel;
    EXPECT_EQ(Slurp(entry.path()), Slurp(b / rel)) << rel << " differs between two runs of one config";
    ++compared;
  }
  // config.yaml, runs/per_robot/links/queries/messages CSVs, summary.json,
  // centroids of 2 runs, LCM logs of 2 robot counts x 2 networks x 2 strategies.
  EXPECT_GE(compared, 7 + 2 + 8);
  for (const char* f : {"runs.csv", "queries.csv", "messages.csv", "per_robot.csv"}) {
    EXPECT_NE(Slurp(a / f), Slurp(c / f)) << f << " did not change with the seed";
  }
}

}  // namespace
