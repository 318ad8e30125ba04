#pragma once
// One robot's own trajectory from a file (issue 35, item 1): KITTI (12 numbers a line, times from
// `fps` or a times file), TUM (`t x y z qx qy qz qw`) or CSV with Kimera-Multi's columns
// (`timestamp_kf(ns)` or `timestamp_ns`, x, y, z, qw, qx, qy, qz, any order, others ignored).
// Every robot's poses lie in one world frame: dvpr does not transform between frames, so the
// sources of a team must all name the same `frame` (CheckOneWorldFrame). The heading is the
// camera's forward axis, as for KITTI: the rotation's third column, R(q) (0, 0, 1) for a
// quaternion.
//
// A CSV's time column holds nanoseconds: each value a whole number in digits in
// [0, 9223372036854775807] (int64), else an error naming the file, line and column ("out of range"
// beyond it; for a value such as 1317643200.5, what it would be as seconds). Poses less than 1 us
// apart on average (over the whole file: last minus first < 1000 ns x (poses - 1)) are refused as
// seconds or milliseconds written where nanoseconds were meant: no camera or odometry runs at
// 1 MHz, and a time in seconds (1317643200, 1317643201, ...) puts its poses a few ns apart. Every
// format's poses lie within 360000000 s (100000 h) of the first pose, as a robot's start does, so
// a robot's times on the team's clock fit in int64 nanoseconds. Every reader skips a UTF-8
// byte-order mark before the first line and refuses a path that is not a regular file (a folder,
// a FIFO, a device, a loop of symbolic links; text_file.h) without opening it.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/domain/data/dataset.h"

namespace dvpr {

enum class TrajectoryFormat { kKitti, kTum, kCsv };
// Their names in a config (dataset.trajectories[].format), in the enum's order.
inline constexpr std::array<std::string_view, 3> kTrajectoryFormatNames{"kitti", "tum", "csv"};

struct TrajectorySource {
  std::filesystem::path poses;
  TrajectoryFormat format = TrajectoryFormat::kKitti;
  double fps = 0;                              // kitti without a times file: frames per second
  std::optional<std::filesystem::path> times;  // kitti: one time in seconds a line (KITTI's times.txt)
  double start_s = 0;                          // the robot's first pose on the team's common clock
  std::string frame = "world";                 // the world frame its poses are in
  // The robot's own descriptor file (dataset.source files): one row per pose, in the poses' order
  // (.npy, .bin or .csv, as dataset.descriptors; experiments/domain/data/loaders.h).
  std::optional<std::filesystem::path> descriptors;
  // Throws std::invalid_argument naming the field: kitti without fps or times (or with both),
  // fps or times for another format, fps outside (0, 1000], start_s outside [0, 360000000] s.
  void Validate() const;
  bool operator==(const TrajectorySource&) const = default;
};

struct TimedTrajectory {
  Trajectory trajectory;
  std::vector<double> times_s;  // each pose's time since the robot's first pose: 0, then increasing
};

// Throws std::runtime_error naming the file and line: a missing or short line or column, NaN or
// Inf, a zero quaternion or heading, timestamps not strictly increasing or out of range, CSV
// nanoseconds that are not whole numbers or look like seconds (above), fewer than 2 poses, a times
// file whose length differs from the poses'.
TimedTrajectory LoadRobotTrajectory(const TrajectorySource& source);

// Throws std::invalid_argument unless every source names the same frame (the documented rule).
void CheckOneWorldFrame(const std::vector<TrajectorySource>& sources);

}  // namespace dvpr
