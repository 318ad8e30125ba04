// network.schedule (talk_schedule.h): a CSV of the windows in which each robot can talk, read
// when the config is read, written back as its path, and every bad file one error naming the
// key, the file and the line.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "experiments/config/talk_schedule.h"
#include "tests/config/config_test_support.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

class ConfigScheduleTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing_support::FreshTestDir("config_schedule"); }
  // Writes `csv` as windows.csv and returns the config text that names it.
  std::string With(const std::string& csv) const {
    std::ofstream(dir_ / "windows.csv", std::ios::binary) << csv;
    return "network: {schedule: " + (dir_ / "windows.csv").string() + "}\n";
  }
  std::string File() const { return fs::absolute(dir_ / "windows.csv").lexically_normal().string(); }
  fs::path dir_;
};

TalkWindow Window(std::int64_t from_ms, std::int64_t until_ms) {
  return TalkWindow{SimTime::Millis(from_ms), SimTime::Millis(until_ms)};
}

TEST_F(ConfigScheduleTest, WindowsAreReadByRobotAndStart) {
  const ExperimentConfig c = testing_support::ParseTestConfig(
      With("robot,start_s,end_s\n1,30,40.5\n0,0,10\n\n1,0.25,20\n"));
  EXPECT_EQ(c.network.schedule, fs::path(File()));
  EXPECT_EQ(c.network.windows, (std::vector<ScheduledWindow>{{0, Window(0, 10'000)},
                                                             {1, Window(250, 20'000)},
                                                             {1, Window(30'000, 40'500)}}));
  // Swarm-SLAM's column names, in another order, with an extra column.
  const ExperimentConfig s = testing_support::ParseTestConfig(With("START_S,ROBOT_ID,note,END_S\n5,2,x,6\n"));
  EXPECT_EQ(s.network.windows, (std::vector<ScheduledWindow>{{2, Window(5'000, 6'000)}}));
}

TEST_F(ConfigScheduleTest, TheScheduleIsWrittenBackAsItsPath) {
  const ExperimentConfig c = testing_support::ParseTestConfig(With("robot,start_s,end_s\n0,1,2\n"));
  const std::string emitted = EmitConfig(c);
  EXPECT_NE(emitted.find("schedule: " + File()), std::string::npos) << emitted;
  EXPECT_EQ(ParseConfig(emitted, "/nonexistent", {}, "config.yaml"), c);
  EXPECT_EQ(EmitConfig(testing_support::ParseTestConfig("{}")).find("schedule"), std::string::npos);
}

TEST_F(ConfigScheduleTest, EachBadFileIsOneErrorNamingKeyFileAndLine) {
  const std::string key = "test.yaml: network.schedule: " + File() + ": ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"robot,start,end_s\n0,1,2\n",
       "line 1: expected a header naming the columns robot, start_s and end_s (or ROBOT_ID, START_S, END_S), got "
       "'robot,start,end_s'"},
      {"", "expected a header robot,start_s,end_s and windows, got an empty file"},
      {"robot,start_s,end_s\n", "expected at least one window after the header"},
      {"robot,start_s,end_s\n0,1\n", "line 2: expected 3 comma-separated fields as the header, got 2"},
      {"robot,start_s,end_s\n-1,1,2\n", "line 2: robot: expected an integer in [0, 32767], got '-1'"},
      {"robot,start_s,end_s\n0.5,1,2\n", "line 2: robot: expected an integer in [0, 32767], got '0.5'"},
      {"robot,start_s,end_s\n0,nan,2\n", "line 2: start_s: expected seconds in [0, 360000000], got 'nan'"},
      {"robot,start_s,end_s\n0,1,inf\n", "line 2: end_s: expected seconds in [0, 360000000], got 'inf'"},
      {"robot,start_s,end_s\n0,-1,2\n", "line 2: start_s: expected seconds in [0, 360000000], got '-1'"},
      {"robot,start_s,end_s\n0,1,\n", "line 2: end_s: expected seconds in [0, 360000000], got ''"},
      {"robot,start_s,end_s\n0,2,2\n", "line 2: end_s must be after start_s"},
      {"robot,start_s,end_s\n0,0,10\n1,0,10\n0,9,12\n", "lines 2 and 4: robot 0's windows overlap"},
  };
  for (const auto& [csv, problem] : cases) {
    EXPECT_EQ(testing_support::ConfigErrorOf(With(csv)), key + problem) << csv;
  }
  EXPECT_EQ(testing_support::ConfigErrorOf("network: {schedule: " + (dir_ / "none.csv").string() + "}\n")
                .rfind("test.yaml: network.schedule: ", 0),
            0u);
}

// Issue 53: a FIFO, a device, a loop of symbolic links and a folder are named as what they are,
// under the key, found by stat: the FIFO is never opened, by the config nor by the reader itself.
TEST_F(ConfigScheduleTest, APathThatIsNotARegularFileIsNamedAndNeverOpened) {
  const fs::path fifo = dir_ / "fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink(dir_ / "loop_b", dir_ / "loop_a");
  fs::create_symlink(dir_ / "loop_a", dir_ / "loop_b");
  fs::create_directory(dir_ / "folder");
  const std::vector<std::pair<fs::path, std::string>> cases = {{fifo, "is a FIFO, not a regular file"},
                                                                {"/dev/zero", "is a device, not a regular file"},
                                                                {dir_ / "loop_a", "is a loop of symbolic links"},
                                                                {dir_ / "folder", "is a folder, not a regular file"}};
  for (const auto& [path, problem] : cases) {
    EXPECT_EQ(testing_support::ConfigErrorOf("network: {schedule: " + path.string() + "}\n"),
              "test.yaml: network.schedule: '" + path.string() + "' " + problem);
    try {
      ReadTalkSchedule(path);
      ADD_FAILURE() << "no error for " << path;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), path.string() + ": " + problem);
    }
  }
  // A symbolic link to the file is the file.
  With("robot,start_s,end_s\n0,1,2\n");
  fs::create_symlink(dir_ / "windows.csv", dir_ / "link.csv");
  const ExperimentConfig c =
      testing_support::ParseTestConfig("network: {schedule: " + (dir_ / "link.csv").string() + "}\n");
  EXPECT_EQ(c.network.windows, (std::vector<ScheduledWindow>{{0, Window(1'000, 2'000)}}));
}

// Issue 53: a UTF-8 byte-order mark before the header is skipped (it made "robot" unknown);
// bytes of the file quoted in an error are escaped.
TEST_F(ConfigScheduleTest, AByteOrderMarkIsSkippedAndQuotedBytesAreEscaped) {
  const ExperimentConfig c = testing_support::ParseTestConfig(With("\xEF\xBB\xBFrobot,start_s,end_s\n0,1,2\n"));
  EXPECT_EQ(c.network.windows, (std::vector<ScheduledWindow>{{0, Window(1'000, 2'000)}}));
  const ExperimentConfig s = testing_support::ParseTestConfig(With("\xEF\xBB\xBFROBOT_ID,START_S,END_S\n3,5,6\n"));
  EXPECT_EQ(s.network.windows, (std::vector<ScheduledWindow>{{3, Window(5'000, 6'000)}}));
  const std::string key = "test.yaml: network.schedule: " + File() + ": ";
  EXPECT_EQ(testing_support::ConfigErrorOf(With("robot,start\x01_s,end_s\n0,1,2\n")),
            key + "line 1: expected a header naming the columns robot, start_s and end_s (or ROBOT_ID, START_S, END_S), "
                  "got 'robot,start\\x01_s,end_s'");
  EXPECT_EQ(testing_support::ConfigErrorOf(With("robot,start_s,end_s\n\xEF\xBB\xBF" "0,1,2\n")),
            key + "line 2: robot: expected an integer in [0, 32767], got '\\xef\\xbb\\xbf0'");
  EXPECT_EQ(testing_support::ConfigErrorOf(With("robot,start_s,end_s\n0,1\xff,2\n")),
            key + "line 2: start_s: expected seconds in [0, 360000000], got '1\\xff'");
}

// Issue 53: a header naming one column twice (robot and ROBOT_ID, any case) is refused: either
// could be meant.
TEST_F(ConfigScheduleTest, AColumnNamedTwiceIsRefusedNamingBoth) {
  const std::string key = "test.yaml: network.schedule: " + File() + ": line 1: the header names both ";
  EXPECT_EQ(testing_support::ConfigErrorOf(With("robot,start_s,end_s,ROBOT_ID\n0,1,2,1\n")),
            key + "'robot' (column 1) and 'ROBOT_ID' (column 4); keep one");
  EXPECT_EQ(testing_support::ConfigErrorOf(With("START_S,robot,start_s,end_s\n1,0,1,2\n")),
            key + "'START_S' (column 1) and 'start_s' (column 3); keep one");
  EXPECT_EQ(testing_support::ConfigErrorOf(With("robot,end_s,start_s,End_S\n0,2,1,2\n")),
            key + "'end_s' (column 2) and 'End_S' (column 4); keep one");
}

// Issue 53: a window of a robot that no team of the sweep has would be ignored in every run.
// Robots 2 and 3: robot 2 is in the team of 3, robot 3 in none (the largest id is 2).
TEST_F(ConfigScheduleTest, ARobotInNoTeamOfTheSweepIsRefused) {
  const ExperimentConfig c = testing_support::ParseTestConfig("robots: [2, 3]\n" + With("robot,start_s,end_s\n2,0,1\n"));
  EXPECT_EQ(c.network.windows, (std::vector<ScheduledWindow>{{2, Window(0, 1'000)}}));
  EXPECT_EQ(testing_support::ConfigErrorOf("robots: [2, 3]\n" + With("robot,start_s,end_s\n2,0,1\n3,0,1\n")),
            "test.yaml: network.schedule: " + File() +
                ": line 3: robot 3 is in no team of the sweep (its largest robot id is 2)");
  EXPECT_EQ(testing_support::ConfigErrorOf("robots: {from: 2, to: 20}\n" + With("robot,start_s,end_s\n20,0,1\n")),
            "test.yaml: network.schedule: " + File() +
                ": line 2: robot 20 is in no team of the sweep (its largest robot id is 19)");
}

}  // namespace
}  // namespace dvpr
