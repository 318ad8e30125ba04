// One robot's trajectory from a KITTI, TUM or CSV file (robot_trajectory.h): files written here,
// read back against hand-worked positions, headings and times, and each bad file one error
// naming the file and line.
#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/robot_trajectory.h"
#include "tests/test_support.h"

namespace dvpr {
namespace {

namespace fs = std::filesystem;

class RobotTrajectoryTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing_support::FreshTestDir("robot_trajectory"); }
  fs::path Write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  static TrajectorySource Source(const fs::path& p, TrajectoryFormat f) {
    TrajectorySource s;
    s.poses = p;
    s.format = f;
    return s;
  }
  std::string ErrorOf(const TrajectorySource& s) const {
    try {
      LoadRobotTrajectory(s);
    } catch (const std::exception& e) {
      return e.what();
    }
    return "(no error)";
  }
  fs::path dir_;
};

// sin(45 deg): a quaternion of 90 degrees about the camera's vertical (y) axis is (w, 0, s, 0)
// with s = w = sqrt(1/2); it turns the forward axis z onto +x (R = [[0 0 1] [0 1 0] [-1 0 0]]).
const double s = std::sqrt(0.5);

void ExpectRow(const Eigen::RowVector3d& row, double x, double y, double z) {
  EXPECT_NEAR(row(0), x, 1e-12);
  EXPECT_NEAR(row(1), y, 1e-12);
  EXPECT_NEAR(row(2), z, 1e-12);
}

TEST_F(RobotTrajectoryTest, TumPosesTimesAndHeadings) {
  const fs::path p = Write("r.tum", "# timestamp tx ty tz qx qy qz qw\n"
                                    "100.0 1 2 3 0 0 0 1\n"
                                    "100.5 4 5 6 0 0.7071067811865476 0 0.7071067811865476\n"
                                    "101 7 8 9 0 -0.7071067811865476 0 0.7071067811865476\n");
  const TimedTrajectory t = LoadRobotTrajectory(Source(p, TrajectoryFormat::kTum));
  ASSERT_EQ(t.trajectory.size(), 3);
  EXPECT_EQ(t.times_s, (std::vector<double>{0.0, 0.5, 1.0}));
  ExpectRow(t.trajectory.positions.row(1), 4, 5, 6);
  ExpectRow(t.trajectory.headings.row(0), 0, 0, 1);   // no rotation: forward is z
  ExpectRow(t.trajectory.headings.row(1), 1, 0, 0);   // +90 degrees about y
  ExpectRow(t.trajectory.headings.row(2), -1, 0, 0);  // -90 degrees about y
}

TEST_F(RobotTrajectoryTest, CsvWithKimeraMultiColumnsInAnyOrder) {
  const fs::path a = Write("a.csv", "timestamp_kf(ns),x,y,z,qw,qx,qy,qz\n"
                                    "1000000000,1,2,3,1,0,0,0\n"
                                    "1250000000,4,5,6," + std::to_string(s) + ",0," + std::to_string(s) + ",0\n");
  const TimedTrajectory t = LoadRobotTrajectory(Source(a, TrajectoryFormat::kCsv));
  EXPECT_EQ(t.times_s, (std::vector<double>{0.0, 0.25}));
  ExpectRow(t.trajectory.positions.row(0), 1, 2, 3);
  // std::to_string keeps 6 decimals: the quaternion is normalised, so the heading is still +x.
  ExpectRow(t.trajectory.headings.row(1), 1, 0, 0);
  const fs::path b = Write("b.csv", "qz,qy,qx,qw,note,z,y,x,timestamp_ns\n0,0,0,2,a,3,2,1,5000\n0,0,0,1,b,6,5,4,7000\n");
  const TimedTrajectory u = LoadRobotTrajectory(Source(b, TrajectoryFormat::kCsv));
  EXPECT_EQ(u.times_s[1], 2e-6);  // 2000 ns / 1e9, one correctly rounded division
  ExpectRow(u.trajectory.positions.row(1), 4, 5, 6);
  ExpectRow(u.trajectory.headings.row(0), 0, 0, 1);  // (2, 0, 0, 0) normalised: no rotation
}

TEST_F(RobotTrajectoryTest, KittiWithFpsOrATimesFile) {
  const fs::path p = Write("k.txt", "1 0 0 1 0 1 0 2 0 0 1 3\n0 0 1 4 0 1 0 5 -1 0 0 6\n1 0 0 7 0 1 0 8 0 0 1 9\n");
  TrajectorySource src = Source(p, TrajectoryFormat::kKitti);
  src.fps = 10;
  const TimedTrajectory t = LoadRobotTrajectory(src);
  EXPECT_EQ(t.times_s, (std::vector<double>{0.0, 0.1, 0.2}));
  ExpectRow(t.trajectory.positions.row(1), 4, 5, 6);
  ExpectRow(t.trajectory.headings.row(1), 1, 0, 0);  // R's third column: values 3, 7, 11 = 1, 0, 0
  src.fps = 0;
  src.times = Write("times.txt", "3.5\n3.75\n4.5\n");
  EXPECT_EQ(LoadRobotTrajectory(src).times_s, (std::vector<double>{0.0, 0.25, 1.0}));
}

TEST_F(RobotTrajectoryTest, TheShippedKittiPosesLoadAsTheDatasetLoaderReadsThem) {
  const fs::path p = fs::path(DVPR_SOURCE_DIR) / "data/kitti/00_poses.txt";
  TrajectorySource src = Source(p, TrajectoryFormat::kKitti);
  src.fps = 10;
  const TimedTrajectory t = LoadRobotTrajectory(src);
  const Trajectory ref = LoadKittiPoses(p);
  EXPECT_EQ(t.trajectory.positions, ref.positions);
  EXPECT_EQ(t.trajectory.headings, ref.headings);
  ASSERT_EQ(t.times_s.size(), 4541u);
  EXPECT_DOUBLE_EQ(t.times_s.back(), 454.0);
}

TEST_F(RobotTrajectoryTest, EachBadFileIsOneErrorNamingFileAndLine) {
  const auto tum = [&](const std::string& text) { return ErrorOf(Source(Write("bad.tum", text), TrajectoryFormat::kTum)); };
  const std::string f = (dir_ / "bad.tum").string() + ": ";
  EXPECT_EQ(tum("0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 1\n0.5 0 0 0 0 0 0 1\n"),
            f + "line 3: timestamp is not after the previous pose's (timestamps must increase)");
  EXPECT_EQ(tum("0 0 0 0 0 0 0 1\n0 1 0 0 0 0 0 1\n"),
            f + "line 2: timestamp is not after the previous pose's (timestamps must increase)");
  EXPECT_EQ(tum("0 0 0 0 0 0 0 1\n1 0 nan 0 0 0 0 1\n"), f + "line 2: NaN or Inf: 'nan'");
  EXPECT_EQ(tum("0 0 0 0 0 0 0 1\n1 0 0 0 0 0 1\n"), f + "line 2: expected 8 numbers (t x y z qx qy qz qw), got 7");
  EXPECT_EQ(tum("# only one pose\n0 0 0 0 0 0 0 1\n"), f + "expected at least 2 poses, got 1");
  EXPECT_EQ(tum("0 0 0 0 0 0 0 1\n1 0 0 0 0 0 0 0\n"), f + "line 2: the quaternion is zero (no rotation)");

  const fs::path csv = Write("bad.csv", "timestamp_ns,x,y,z,qw,qx,qy\n0,0,0,0,1,0,0\n1,0,0,0,1,0,0\n");
  EXPECT_EQ(ErrorOf(Source(csv, TrajectoryFormat::kCsv)),
            csv.string() + ": line 1: the header has no column qz (expected timestamp_kf(ns) or timestamp_ns, x, "
                           "y, z, qw, qx, qy, qz)");
  const fs::path short_line = Write("short.csv", "timestamp_ns,x,y,z,qw,qx,qy,qz\n0,0,0,0,1,0,0,0\n1,0,0,0,1,0\n");
  EXPECT_EQ(ErrorOf(Source(short_line, TrajectoryFormat::kCsv)),
            short_line.string() + ": line 3: expected 8 fields as the header, got 6");

  TrajectorySource kitti = Source(Write("k.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n"),
                                  TrajectoryFormat::kKitti);
  EXPECT_EQ(ErrorOf(kitti), "format kitti: give fps or a times file, one of them");
  kitti.times = Write("t.txt", "0\n0.1\n0.2\n");
  EXPECT_EQ(ErrorOf(kitti), (dir_ / "t.txt").string() + ": 3 times for the 2 poses of " + (dir_ / "k.txt").string());
  kitti.times = Write("t.txt", "0\n0\n");
  EXPECT_EQ(ErrorOf(kitti),
            (dir_ / "t.txt").string() + ": line 2: timestamp is not after the previous pose's (timestamps must increase)");
  TrajectorySource tum_fps = Source(dir_ / "bad.tum", TrajectoryFormat::kTum);
  tum_fps.fps = 10;
  EXPECT_EQ(ErrorOf(tum_fps), "fps and times apply to format kitti only (tum and csv files carry their times)");
}

// Issue 53: a FIFO, a device, a loop of symbolic links and a folder, as the poses of each format
// or as a times file, are each named as what they are, found by stat: the FIFO is never opened
// (no writer comes, so opening it would wait for ever). A link to a regular file is that file.
TEST_F(RobotTrajectoryTest, APathThatIsNotARegularFileIsNamedAndNeverOpened) {
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
    EXPECT_EQ(ErrorOf(Source(path, TrajectoryFormat::kTum)), path.string() + ": " + problem);
    EXPECT_EQ(ErrorOf(Source(path, TrajectoryFormat::kCsv)), path.string() + ": " + problem);
    TrajectorySource kitti = Source(path, TrajectoryFormat::kKitti);
    kitti.fps = 10;
    EXPECT_EQ(ErrorOf(kitti), path.string() + ": " + problem);
    kitti = Source(Write("k.txt", "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n"), TrajectoryFormat::kKitti);
    kitti.times = path;
    EXPECT_EQ(ErrorOf(kitti), path.string() + ": " + problem);
  }
  fs::create_symlink(Write("r.tum", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n"), dir_ / "link.tum");
  EXPECT_EQ(LoadRobotTrajectory(Source(dir_ / "link.tum", TrajectoryFormat::kTum)).times_s,
            (std::vector<double>{0.0, 1.0}));
}

// Issue 53: a UTF-8 byte-order mark (EF BB BF) before the first line, as some editors save a
// CSV, is skipped in every format; anywhere else it is text, quoted with its bytes escaped.
TEST_F(RobotTrajectoryTest, AByteOrderMarkBeforeTheFirstLineIsSkipped) {
  const std::string bom = "\xEF\xBB\xBF";
  const fs::path csv = Write("bom.csv", bom + "timestamp_kf(ns),x,y,z,qw,qx,qy,qz\n"
                                              "1000000000,1,2,3,1,0,0,0\n1500000000,4,5,6,1,0,0,0\n");
  EXPECT_EQ(LoadRobotTrajectory(Source(csv, TrajectoryFormat::kCsv)).times_s, (std::vector<double>{0.0, 0.5}));
  const fs::path tum = Write("bom.tum", bom + "# timestamp tx ty tz qx qy qz qw\n100 1 2 3 0 0 0 1\n101 4 5 6 0 0 0 1\n");
  EXPECT_EQ(LoadRobotTrajectory(Source(tum, TrajectoryFormat::kTum)).times_s, (std::vector<double>{0.0, 1.0}));
  TrajectorySource kitti =
      Source(Write("bom.txt", bom + "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n"), TrajectoryFormat::kKitti);
  kitti.times = Write("bom_times.txt", bom + "3.5\n3.75\n");
  EXPECT_EQ(LoadRobotTrajectory(kitti).times_s, (std::vector<double>{0.0, 0.25}));
  const fs::path late = Write("late.tum", "100 1 2 3 0 0 0 1\n" + bom + "101 4 5 6 0 0 0 1\n");
  EXPECT_EQ(ErrorOf(Source(late, TrajectoryFormat::kTum)), late.string() + ": line 2: not a number: '\\xef\\xbb\\xbf101'");
}

// Issue 53: a nanosecond timestamp beyond int64 (or below 0) is out of range at its line, not a
// garbled time further on; within int64, a time more than 100000 h after the first pose is too.
TEST_F(RobotTrajectoryTest, TimestampsOutOfRangeAreOneErrorAtTheirLine) {
  const std::string f = (dir_ / "ns.csv").string() + ": ";
  const auto csv = [&](const std::string& rows) {
    return ErrorOf(Source(Write("ns.csv", "timestamp_ns,x,y,z,qw,qx,qy,qz\n" + rows), TrajectoryFormat::kCsv));
  };
  EXPECT_EQ(csv("1000000000,0,0,0,1,0,0,0\n99999999999999999999,1,0,0,1,0,0,0\n"),
            f + "line 3: timestamp_ns: 99999999999999999999 is out of range (nanoseconds must be a whole number in "
                "[0, 9223372036854775807])");
  EXPECT_EQ(csv("-1,0,0,0,1,0,0,0\n1000000000,1,0,0,1,0,0,0\n"),
            f + "line 2: timestamp_ns: -1 is out of range (nanoseconds must be a whole number in [0, 9223372036854775807])");
  // 360000000 s after the first pose is the most; 360000001 s is past it.
  EXPECT_EQ(csv("0,0,0,0,1,0,0,0\n360000000000000000,1,0,0,1,0,0,0\n"), "(no error)");
  EXPECT_EQ(csv("0,0,0,0,1,0,0,0\n360000001000000000,1,0,0,1,0,0,0\n"),
            f + "line 3: timestamp is out of range: more than 360000000 s (100000 h) after the first pose's");
  const fs::path tum = Write("far.tum", "5 0 0 0 0 0 0 1\n360000006 1 0 0 0 0 0 1\n");
  EXPECT_EQ(ErrorOf(Source(tum, TrajectoryFormat::kTum)),
            tum.string() + ": line 2: timestamp is out of range: more than 360000000 s (100000 h) after the first pose's");
}

// Issue 53: seconds in a nanosecond column. A value that is not a whole number is refused with
// what it is as seconds; whole seconds put the poses a few ns apart, and less than 1 us between
// poses on average (a source faster than 1 MHz) is refused at the last line.
TEST_F(RobotTrajectoryTest, SecondsInANanosecondColumnAreRefused) {
  const std::string f = (dir_ / "s.csv").string() + ": ";
  const auto csv = [&](const std::string& column, const std::string& rows) {
    return ErrorOf(Source(Write("s.csv", column + ",x,y,z,qw,qx,qy,qz\n" + rows), TrajectoryFormat::kCsv));
  };
  EXPECT_EQ(csv("timestamp_kf(ns)", "1317643200,0,0,0,1,0,0,0\n1317643200.5,1,0,0,1,0,0,0\n"),
            f + "line 3: timestamp_kf(ns): expected a whole number of nanoseconds, got '1317643200.5' (seconds? "
                "1317643200.5 s is 1317643200500000000 ns)");
  // 3 poses 2 ns apart in all: 2 ns < 2 x 1000 ns.
  EXPECT_EQ(csv("timestamp_ns", "1317643200,0,0,0,1,0,0,0\n1317643201,1,0,0,1,0,0,0\n1317643202,2,0,0,1,0,0,0\n"),
            f + "line 4: timestamp_ns: 3 poses in 2 ns, less than 1 us apart on average: seconds or milliseconds where "
                "nanoseconds were meant? As seconds, line 2's 1317643200 is 1317643200000000000 ns");
  // 1 us apart on average is accepted (1999 ns would not be: below 2 x 1000 ns).
  EXPECT_EQ(csv("timestamp_ns", "5000,0,0,0,1,0,0,0\n6000,1,0,0,1,0,0,0\n6999,2,0,0,1,0,0,0\n"),
            f + "line 4: timestamp_ns: 3 poses in 1999 ns, less than 1 us apart on average: seconds or milliseconds where "
                "nanoseconds were meant? As seconds, line 2's 5000 is 5000000000000 ns");
  Write("s.csv", "timestamp_ns,x,y,z,qw,qx,qy,qz\n5000,0,0,0,1,0,0,0\n6000,1,0,0,1,0,0,0\n7000,2,0,0,1,0,0,0\n");
  EXPECT_EQ(LoadRobotTrajectory(Source(dir_ / "s.csv", TrajectoryFormat::kCsv)).times_s,
            (std::vector<double>{0.0, 1e-6, 2e-6}));
}

TEST(RobotTrajectoryFrames, RobotsInDifferentFramesAreRefused) {
  std::vector<TrajectorySource> team(3);
  team[2].frame = "robot2_odom";
  try {
    CheckOneWorldFrame(team);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "trajectories[2].frame: 'robot2_odom' differs from trajectories[0]'s 'world': every robot's poses must "
              "lie in one world frame (dvpr does not transform between frames)");
  }
  team[2].frame = "world";
  EXPECT_NO_THROW(CheckOneWorldFrame(team));
}

}  // namespace
}  // namespace dvpr
