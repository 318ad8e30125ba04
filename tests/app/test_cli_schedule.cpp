// network.schedule through the dvpr binary (issue 35, item 3): a robot whose only talk window
// lies after the mission receives no query in either method, while without the schedule it
// serves its share; a launched team refuses the key. The windows' timing is hand-worked at the
// network's level (tests/net_models/network/test_talk_windows.cpp).
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/app/cli_test_support.h"

namespace dvpr::testing_support {
namespace {

namespace fs = std::filesystem;

class ScheduleCliTest : public CliTest {
 protected:
  // 300 frames of KITTI 00 (30 s at 10 fps) for 3 robots on point-to-point links.
  std::string Yaml(const std::string& network_extra = "") const {
    return "name: schedule\nseed: 1\ndataset: {source: synthetic, poses: '" + std::string(DVPR_SOURCE_DIR) +
           "/data/kitti/00_poses.txt', dim: 16, fps: 10, frames: 300}\ntraining: {synthetic: {samples: 500}}\n"
           "robots: [3]\nruns: 1\nprotocols: [sim]\nstrategies: [decentralized, broadcast]\n"
           "evaluation: {gt_radius_m: 5, suppression_frames: 50}\n"
           "network: {model: point_to_point" + network_extra + "}\noutputs: {figures: false}\n";
  }
  // per_robot.csv's queries_received by (strategy, robot).
  std::map<std::pair<std::string, int>, long> Received() const {
    std::ifstream in(Out() / "per_robot.csv");
    std::string line;
    std::getline(in, line);
    std::vector<std::string> header;
    {
      std::istringstream h(line);
      for (std::string f; std::getline(h, f, ',');) header.push_back(f);
    }
    const auto col = [&](const std::string& name) {
      for (std::size_t i = 0; i < header.size(); ++i) {
        if (header[i] == name) return i;
      }
      ADD_FAILURE() << "no column " << name;
      return std::size_t{0};
    };
    const std::size_t strategy = col("strategy"), robot = col("robot"), received = col("queries_received");
    std::map<std::pair<std::string, int>, long> out;
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::istringstream s(line);
      for (std::string x; std::getline(s, x, ',');) f.push_back(x);
      out[{f[strategy], std::stoi(f[robot])}] = std::stol(f[received]);
    }
    return out;
  }
};

TEST_F(ScheduleCliTest, ARobotOutsideItsWindowsReceivesNothing) {
  {
    const Result r = RunConfig(Yaml());
    ASSERT_EQ(r.status, 0) << r.err;
  }
  // 300 frames, 100 a robot. In broadcast every robot searches every query of the team: its
  // own where it took them, the others' as they arrive: 300 each.
  const auto all = Received();
  for (int robot = 0; robot < 3; ++robot) EXPECT_EQ(all.at({"broadcast", robot}), 300) << robot;
  // Robot 2 talks only from 1000 s, long after the 30 s mission; robot 0 from 0 to 100 s, all of it.
  std::ofstream(dir_ / "windows.csv") << "robot,start_s,end_s\n2,1000,1001\n0,0,100\n";
  fs::remove_all(Out());
  const Result r = RunConfig(Yaml(", schedule: '" + (dir_ / "windows.csv").string() + "'"));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto windowed = Received();
  // Robots 0 and 1 search their own 100 and each other's 100; robot 2 only its own 100.
  EXPECT_EQ(windowed.at({"broadcast", 0}), 200);
  EXPECT_EQ(windowed.at({"broadcast", 1}), 200);
  EXPECT_EQ(windowed.at({"broadcast", 2}), 100);
  // Decentralized: robot 2 searches only its own queries of its own clusters, and the team loses
  // every query that crosses between robot 2 and the others.
  EXPECT_LT(windowed.at({"decentralized", 2}), all.at({"decentralized", 2}));
  long sum = 0, before = 0;
  for (int robot = 0; robot < 3; ++robot) {
    sum += windowed.at({"decentralized", robot});
    before += all.at({"decentralized", robot});
  }
  EXPECT_EQ(before, 300);
  EXPECT_LT(sum, 300);
  std::ifstream config(Out() / "config.yaml");
  std::stringstream text;
  text << config.rdbuf();
  EXPECT_NE(text.str().find("schedule: " + (dir_ / "windows.csv").string()), std::string::npos) << text.str();
}

TEST_F(ScheduleCliTest, ABadScheduleIsOneErrorAndNothingIsWritten) {
  std::ofstream(dir_ / "windows.csv") << "robot,start_s,end_s\n0,5,1\n";
  const Result r = RunConfig(Yaml(", schedule: '" + (dir_ / "windows.csv").string() + "'"));
  ExpectConfigError(r, "bad.yaml: network.schedule: " + (dir_ / "windows.csv").string() + ": line 2: end_s must be after start_s");
  EXPECT_FALSE(fs::exists(Out()));
}

}  // namespace
}  // namespace dvpr::testing_support
