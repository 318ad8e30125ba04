// Loading a config's inputs: errors that need the data name the config key.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/domain/data/npy.h"
#include "experiments/protocols/inputs.h"

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

}  // namespace
}  // namespace dvpr
