// Where the robots are: config.yaml's pose file, its first dataset.frames, split as the simulation
// splits it; and a whole replay written (or, on an error, nothing).
#include <sstream>

#include <gtest/gtest.h>

#include "experiments/replay/replay.h"
#include "experiments/replay/replay_tracks.h"
#include "tests/replay/replay_test_support.h"

namespace dvpr::replay {
namespace {

class ReplayTracksTest : public ReplayFolderTest {
 protected:
  // Five KITTI poses (identity rotation), frame f at x = f + 0.5, z = -2f; a config using four,
  // on the default network (point-to-point 10 Mbit/s 2 ms) or `network`.
  void WriteInputs(const std::string& network = "") const {
    std::string poses;
    for (int f = 0; f < 5; ++f) {
      poses += "1 0 0 " + std::to_string(f + 0.5) + " 0 1 0 0 0 0 1 " + std::to_string(-2 * f) + "\n";
    }
    Write("poses.txt", poses);
    Write("config.yaml", "name: tiny\ndataset: {poses: " + (dir_ / "poses.txt").string() + ", fps: 5, frames: 4}\n" +
                             (network.empty() ? "" : "network: " + network + "\n"));
  }
};

TEST_F(ReplayTracksTest, SplitAsTheSimulationSplitsTheFirstFrames) {
  WriteInputs();
  const Tracks t = LoadTracks(dir_ / "config.yaml", 3);  // 4 frames, 3 robots: [0,1) [1,2) [2,4)
  EXPECT_EQ(t.name, "tiny");
  EXPECT_EQ(t.fps, 5);
  ASSERT_EQ(t.robots.size(), 3u);
  EXPECT_EQ(t.robots[0].first_frame, 0);
  EXPECT_EQ(t.robots[1].first_frame, 1);
  EXPECT_EQ(t.robots[2].first_frame, 2);
  EXPECT_EQ(t.robots[0].x, (std::vector<double>{0.5}));
  EXPECT_EQ(t.robots[2].x, (std::vector<double>{2.5, 3.5}));
  EXPECT_EQ(t.robots[2].z, (std::vector<double>{-4, -6}));
}

TEST_F(ReplayTracksTest, MissingConfigOrPosesNameTheFile) {
  EXPECT_EQ(ErrorOf([&] { LoadTracks(dir_ / "config.yaml", 2); }),
            (dir_ / "config.yaml").string() + ": not found (a replay needs the result folder's config.yaml)");
  Write("config.yaml", "name: tiny\ndataset: {poses: " + (dir_ / "gone.txt").string() + "}\n");
  const std::string e = ErrorOf([&] { LoadTracks(dir_ / "config.yaml", 2); });
  EXPECT_NE(e.find("dataset.poses"), std::string::npos) << e;
  EXPECT_NE(e.find("gone.txt"), std::string::npos) << e;
}

TEST_F(ReplayTracksTest, WritesOnePageOrNothing) {
  WriteInputs();
  Write("messages.csv", std::string(kHeader) +
      "sim,decentralized,2,0,0,2000,0,1,DVPR_QUERY_1,x,query_t,536,587,0,0,point_to_point,1e+07,2,none,q\n"
      "sim,broadcast,2,0,0,2000,1,0,DVPR_QUERY_ALL,x,query_t,536,589,0,0,point_to_point,1e+07,2,none,q\n");
  ReplayOptions o;
  o.dir = dir_;
  std::ostringstream out;
  const std::filesystem::path page = WriteReplay(o, out);
  EXPECT_EQ(page, dir_ / "replay_n2_run0_net0.html");
  EXPECT_TRUE(std::filesystem::is_regular_file(page));
  EXPECT_EQ(out.str().rfind("replay of tiny: 2 robots, run 0, network 0 (point-to-point, 10 Mbit/s, 2 ms), "
                            "decentralized vs broadcast, 2 messages: " + page.string(), 0), 0u) << out.str();
  std::filesystem::remove(page);
  o.selection.run = 3;
  EXPECT_NE(ErrorOf([&] { WriteReplay(o, out); }).find("no messages of run=3"), std::string::npos);
  o.selection.run.reset();
  std::filesystem::remove(dir_ / "poses.txt");
  EXPECT_NE(ErrorOf([&] { WriteReplay(o, out); }).find("dataset.poses"), std::string::npos);
  for (const auto& e : std::filesystem::directory_iterator(dir_)) {
    EXPECT_EQ(e.path().extension(), e.path().filename() == "config.yaml" ? ".yaml" : ".csv") << e.path();
  }
}

// Issue 53: a wifi result folder was refused (its latency_ms is empty: wifi has none); it is
// replayed, named without a latency.
TEST_F(ReplayTracksTest, AWifiFolderIsReplayed) {
  WriteInputs("{model: wifi, wifi: {rate: 6Mbps}}");
  Write("messages.csv", std::string(kHeader) +
      "sim,decentralized,2,0,0,2000,0,1,DVPR_QUERY_1,x,query_t,536,587,0,0,wifi,6e+06,,none,q\n"
      "sim,broadcast,2,0,0,2000,1,0,DVPR_QUERY_ALL,x,query_t,536,589,0,0,wifi,6e+06,,none,q\n");
  ReplayOptions o;
  o.dir = dir_;
  std::ostringstream out;
  const std::filesystem::path page = WriteReplay(o, out);
  EXPECT_TRUE(std::filesystem::is_regular_file(page));
  EXPECT_EQ(out.str().rfind("replay of tiny: 2 robots, run 0, network 0 (wifi, 6 Mbit/s), decentralized vs broadcast, "
                            "2 messages: " + page.string(), 0), 0u) << out.str();
}

TEST_F(ReplayTracksTest, FoldersThatCannotBeReplayed) {
  ReplayOptions o;
  o.dir = dir_ / "absent";
  std::ostringstream out;
  EXPECT_EQ(ErrorOf([&] { WriteReplay(o, out); }), o.dir.string() + ": no such result folder");
  o.dir = Write("file.txt", "x");
  EXPECT_EQ(ErrorOf([&] { WriteReplay(o, out); }), o.dir.string() + ": not a folder (expected a result folder)");
  o.dir = dir_;
  EXPECT_EQ(ErrorOf([&] { WriteReplay(o, out); }),
            dir_.string() + ": no messages.csv (record it: dvpr run CONFIG --set outputs.messages=true)");
}

TEST(ReplayArgsTest, FlagsAndUsageErrors) {
  const ReplayOptions o = ParseReplayArgs({"replay", "dir", "--robots", "4", "--run", "1", "--network", "2",
                                           "--strategy", "broadcast", "--strategy", "decentralized", "--out", "x.html"});
  EXPECT_EQ(o.dir, "dir");
  EXPECT_EQ(o.selection.robots, 4);
  EXPECT_EQ(o.selection.run, 1);
  EXPECT_EQ(o.selection.network, 2);
  EXPECT_EQ(o.selection.strategies, (std::vector<std::string>{"broadcast", "decentralized"}));
  EXPECT_EQ(o.out, "x.html");
  EXPECT_THROW(ParseReplayArgs({"replay"}), std::invalid_argument);
  EXPECT_THROW(ParseReplayArgs({"replay", "a", "b"}), std::invalid_argument);
  EXPECT_THROW(ParseReplayArgs({"replay", "a", "--run", "-1"}), std::invalid_argument);
  EXPECT_THROW(ParseReplayArgs({"replay", "a", "--run", "x"}), std::invalid_argument);
  EXPECT_THROW(ParseReplayArgs({"replay", "a", "--speed", "2"}), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr::replay
