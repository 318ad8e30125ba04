// network.schedule (talk_schedule.h): a CSV of the windows in which each robot can talk, read
// when the config is read, written back as its path, and every bad file one error naming the
// key, the file and the line.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
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

}  // namespace
}  // namespace dvpr
