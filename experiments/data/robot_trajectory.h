#pragma once
// One robot's own trajectory from a file (issue 35, item 1): KITTI (12 numbers a line, times from
// `fps` or a times file), TUM (`t x y z qx qy qz qw`) or CSV with Kimera-Multi's columns
// (`timestamp_kf(ns)` or `timestamp_ns`, x, y, z, qw, qx, qy, qz, any order, others ignored).
// Every robot's poses lie in one world frame: dvpr does not transform between frames, so the
// sources of a team must all name the same `frame` (CheckOneWorldFrame). The heading is the
// camera's forward axis, as for KITTI: the rotation's third column, R(q) (0, 0, 1) for a
// quaternion.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/data/dataset.h"

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
// Inf, a zero quaternion or heading, timestamps not strictly increasing, fewer than 2 poses, a
// times file whose length differs from the poses'.
TimedTrajectory LoadRobotTrajectory(const TrajectorySource& source);

// Throws std::invalid_argument unless every source names the same frame (the documented rule).
void CheckOneWorldFrame(const std::vector<TrajectorySource>& sources);

}  // namespace dvpr
