// outputs.connectivity (docs/network_model.md, "Connectivity"), as a user runs it: three robots
// on a hand-made layout whose graph is worked out by hand at every frame, written to
// connectivity.csv and summarised in summary.json, the same with one worker or two; nothing
// written without the key; the key without a radio refused in one line.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/app/cli_test_support.h"
#include "tests/test_support.h"

namespace dvpr::testing_support {
namespace {

namespace fs = std::filesystem;

class ConnectivityCliTest : public CliTest {
 protected:
  // 9 frames at 10 fps, 3 robots: robot r drives frames 3r .. 3r + 2 at 0, 0.1 and 0.2 s, along
  // x (the ground plane is x and z). Robot 0 stays at 0; robot 1 is at 150, 150, 1000 m; robot 2
  // at 300, 600, 2000 m.
  void SetUp() override {
    CliTest::SetUp();
    std::ofstream poses(dir_ / "poses.txt");
    for (const int x : {0, 0, 0, 150, 150, 1000, 300, 600, 2000}) poses << "1 0 0 " << x << " 0 1 0 0 0 0 1 0\n";
  }
  std::string Yaml(const std::string& model, const std::string& outputs) const {
    return "name: three\nseed: 1\ndataset: {source: synthetic, poses: '" + (dir_ / "poses.txt").string() +
           "', dim: 8, fps: 10}\ntraining: {synthetic: {samples: 200}}\nrobots: [3]\nruns: 2\nprotocols: [sim]\n"
           "strategies: [decentralized, broadcast]\nevaluation: {gt_radius_m: 5, suppression_frames: 2}\n"
           "network: {model: " + model + "}\noutputs: {figures: false" + outputs + "}\n";
  }
  static constexpr const char* kRadio =
      "[point_to_point, radio], radio: {propagation: range, range: 200m}, routing: shortest_path";
  Result Run(const std::string& yaml, const fs::path& out, const std::string& threads) {
    std::ofstream(Config()) << yaml;
    return Dvpr("run '" + Config().string() + "' --quiet --threads " + threads + " --out '" + out.string() + "'");
  }
};

TEST_F(ConnectivityCliTest, HandWorkedLayoutEveryFrame) {
  ASSERT_EQ(Run(Yaml(kRadio, ", connectivity: true"), Out(), "1").status, 0);
  // Range 200 m. At 0 s: 0-1 (150 m) and 1-2 (150 m) in range, 0-2 (300 m) not: 2 pairs, one
  // component of 3; hops 1 for four ordered pairs and 2 for 0->2 and 2->0: mean 8/6, max 2.
  // At 0.1 s robot 2 is 450 m from robot 1: only 0-1, components {0, 1} and {2}, 1 hop. At 0.2 s
  // robot 1 is 1000 m out: nobody in range, three components of one, no hops. Robots in range,
  // robot by robot: 1 2 1 (robot 1 hears both), then 1 1 0, then none.
  const std::string run =
      "0,2,1,3,1.3333333333333333,2,1 2 1\n"
      "0.1,1,2,2,1,1,1 1 0\n"
      "0.2,0,3,1,0,0,0 0 0\n";
  std::string expected = "protocol,strategy,robots,run,network_variant,time_s,pairs_in_range,components,"
                         "largest_component,mean_hops,max_hops,robots_in_range\n";
  // Only the radio (variant 1) tracks it; spec order: run 0's strategies, then run 1's.
  for (const char* r : {"0", "1"}) {
    for (const char* s : {"decentralized", "broadcast"}) {
      std::istringstream rows(run);
      for (std::string row; std::getline(rows, row);) expected += std::string("sim,") + s + ",3," + r + ",1," + row + "\n";
    }
  }
  EXPECT_EQ(Slurp(Out() / "connectivity.csv"), expected);
  // Connected at 1 of 3 steps; mean hops over the 2 steps with a pair: (8/6 + 1) / 2, which in
  // doubles is 1.3333333333333333 + 1 = 2.333333333333333 (rounded down), halved (python3 agrees).
  const std::string summary = Slurp(Out() / "summary.json");
  EXPECT_NE(summary.find("\"connected_time_share\": 0.3333333333333333, \"connected_pair_mean_hops\": "
                         "1.1666666666666665},\n     \"std\""),
            std::string::npos) << summary;
  // The point-to-point groups (variant 0) have no robots to be in range: no such fields.
  const auto p2p = summary.find("\"network_model\": \"point_to_point\"");
  ASSERT_NE(p2p, std::string::npos);
  EXPECT_EQ(summary.substr(p2p, summary.find("}}", p2p) - p2p).find("connected_"), std::string::npos);
  EXPECT_NE(Slurp(Out() / "config.yaml").find("connectivity: true"), std::string::npos);
  // Two workers finish the runs in any order; the files are the same.
  const fs::path two = dir_ / "two_workers";
  ASSERT_EQ(Run(Yaml(kRadio, ", connectivity: true"), two, "2").status, 0);
  EXPECT_EQ(Slurp(two / "connectivity.csv"), expected);
  EXPECT_EQ(Slurp(two / "summary.json"), summary);
}

TEST_F(ConnectivityCliTest, NothingWithoutTheKey) {
  ASSERT_EQ(Run(Yaml(kRadio, ""), Out(), "1").status, 0);
  EXPECT_FALSE(fs::exists(Out() / "connectivity.csv"));
  EXPECT_EQ(Slurp(Out() / "summary.json").find("connected_"), std::string::npos);
  EXPECT_EQ(Slurp(Out() / "config.yaml").find("connectivity"), std::string::npos);
}

TEST_F(ConnectivityCliTest, WithoutARadioItIsOneNamedError) {
  ExpectConfigError(Run(Yaml("point_to_point", ", connectivity: true"), Out(), "1"),
                    "outputs.connectivity: needs a network variant of model radio");
  // The same through --set, as the quick run does.
  std::ofstream(Config()) << Yaml("shared_medium", "");
  ExpectConfigError(Dvpr("run '" + Config().string() + "' --quiet --set outputs.connectivity=true --out '" +
                         Out().string() + "'"),
                    "outputs.connectivity: needs a network variant of model radio");
}

}  // namespace
}  // namespace dvpr::testing_support
