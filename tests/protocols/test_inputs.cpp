// Loading a config's inputs: errors that need the data name the config key.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/domain/data/npy.h"
#include "experiments/protocols/inputs.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

// dim larger than the descriptors is found when the data is loaded, and names the key.
TEST(InputsTest, DimLargerThanDescriptors) {
  const fs::path dir = fs::path(DVPR_TEST_TMP) / "config_dim";
  fs::create_directories(dir);
  WriteNpy(dir / "d.npy", DescriptorMatrix::Ones(4, 8));
  {
    std::ofstream poses(dir / "poses.txt");
    for (int i = 0; i < 4; ++i) poses << "1 0 0 " << i << " 0 1 0 0 0 0 1 0\n";
  }
  const ExperimentConfig c = ParseConfig(
      "dataset: {source: files, poses: poses.txt, descriptors: d.npy, dim: 16}\nrobots: [2]\n",
      dir, {}, "dim.yaml");
  try {
    LoadSharedInputs(c, "dim.yaml");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("dim.yaml: dataset.descriptors: ", 0), 0u) << what;
    EXPECT_NE(what.find("16"), std::string::npos) << what;
  }
}


// A team of two robots on TUM files of their own (robot 0: 6 poses, robot 1: 4, 20 s later), first
// with the synthetic source, then with each robot's share of that rendering written to its own
// descriptor file (dataset.source files): the same team, poses, times and descriptors.
class TeamDescriptorFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing_support::FreshTestDir("team_descriptor_files");
    std::ofstream r0(dir_ / "r0.txt"), r1(dir_ / "r1.txt");
    for (int k = 0; k < 6; ++k) r0 << k << " " << 3 * k << " 0 " << k << " 0 0 0 1\n";
    for (int k = 0; k < 4; ++k) r1 << 0.5 * k << " " << 15 - 3 * k << " 0 " << 5 - k << " 0 0 0 1\n";
  }
  std::string Yaml(const std::string& source, const std::string& d0, const std::string& d1,
                   const std::string& extra = "") const {
    const auto entry = [](const std::string& poses, const std::string& start, const std::string& desc) {
      return "    - {poses: " + poses + ", format: tum, start: " + start + (desc.empty() ? "" : ", descriptors: " + desc) +
             "}\n";
    };
    return "dataset:\n  source: " + source + "\n  dim: 8\n" + extra + "  trajectories:\n" + entry("r0.txt", "0s", d0) +
           entry("r1.txt", "20s", d1) + "robots: [2]\nprotocols: [paper]\ntraining: {source: deployment}\n";
  }
  SharedInputs Load(const std::string& yaml) {
    config_ = ParseConfig(yaml, dir_, {}, "team.yaml");
    return LoadSharedInputs(config_, "team.yaml");
  }
  std::string LoadError(const std::string& yaml) {
    try {
      Load(yaml);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "(no error)";
  }
  fs::path dir_;
  ExperimentConfig config_;
};

TEST_F(TeamDescriptorFilesTest, EachRobotsOwnFileGivesTheTeamOfTheSyntheticSource) {
  const SharedInputs synthetic = Load(Yaml("synthetic", "", ""));
  ASSERT_EQ(synthetic.deployment.size(), 10);
  WriteNpy(dir_ / "d0.npy", synthetic.deployment.descriptors.topRows(6));
  // Robot 1's as a .csv of 8 values a line: float32 written in its shortest round-trip form.
  {
    std::ofstream csv(dir_ / "d1.csv");
    csv.precision(9);
    for (Eigen::Index i = 6; i < 10; ++i) {
      for (Eigen::Index j = 0; j < 8; ++j) csv << (j ? "," : "") << synthetic.deployment.descriptors(i, j);
      csv << "\n";
    }
  }
  const SharedInputs files = Load(Yaml("files", "d0.npy", "d1.csv"));
  EXPECT_EQ(files.deployment.descriptors, synthetic.deployment.descriptors);
  EXPECT_EQ(files.deployment.trajectory.positions, synthetic.deployment.trajectory.positions);
  ASSERT_TRUE(files.deployment.plan);
  EXPECT_EQ(files.deployment.plan->capture, synthetic.deployment.plan->capture);
  EXPECT_EQ(files.deployment.plan->ranges, synthetic.deployment.plan->ranges);
  // Training on the deployment trains on every robot's rows.
  EXPECT_EQ(files.training, synthetic.training);
}

TEST_F(TeamDescriptorFilesTest, ACountWidthOrDimensionThatDoesNotFitNamesTheRobotsEntryAndTheFile) {
  WriteNpy(dir_ / "six.npy", DescriptorMatrix::Ones(6, 8));
  WriteNpy(dir_ / "five.npy", DescriptorMatrix::Ones(5, 8));
  WriteNpy(dir_ / "four.npy", DescriptorMatrix::Ones(4, 8));
  WriteNpy(dir_ / "wide.npy", DescriptorMatrix::Ones(4, 16));
  WriteNpy(dir_ / "narrow.npy", DescriptorMatrix::Ones(4, 4));
  const std::string r1 = "team.yaml: dataset.trajectories[1].descriptors: ";
  // Robot 1 has 4 poses: 5 rows is one too many.
  EXPECT_EQ(LoadError(Yaml("files", "six.npy", "five.npy")),
            r1 + (dir_ / "five.npy").string() + " has 5 descriptors (rows), but the robot's poses " +
                (dir_ / "r1.txt").string() + " have 4: one row per pose, in the poses' order");
  EXPECT_EQ(LoadError(Yaml("files", "six.npy", "wide.npy")),
            r1 + (dir_ / "wide.npy").string() + " has 16 values per frame, dataset.trajectories[0].descriptors (" +
                (dir_ / "six.npy").string() + ") 8: every robot's descriptors must be of one kind and width");
  // dataset.dim 8 is wider than robot 1's 4 values.
  EXPECT_EQ(LoadError(Yaml("files", "six.npy", "narrow.npy")),
            r1 + (dir_ / "narrow.npy").string() + ": dim 8 is larger than the file's 4 values per frame");
  EXPECT_EQ(LoadError(Yaml("files", "six.npy", "four.npy")), "(no error)");
}

}  // namespace
}  // namespace dvpr
