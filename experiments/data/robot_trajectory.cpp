// One robot's trajectory from a KITTI, TUM or CSV file (robot_trajectory.h).
#include "experiments/data/robot_trajectory.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "experiments/data/loaders.h"
#include "experiments/data/text_file.h"

namespace dvpr {

namespace fs = std::filesystem;
using namespace text_file;  // the text readers shared with loaders.cpp

namespace {

struct Pose {
  double t;
  std::array<double, 3> p;
  std::array<double, 4> q;  // w, x, y, z
};

// The camera's forward axis R(q) (0, 0, 1) of the normalised quaternion.
Eigen::Vector3d Forward(const fs::path& path, std::size_t line, std::array<double, 4> q) {
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(norm > 1e-9)) FailLine(path, line, "the quaternion is zero (no rotation)");
  if (!std::isfinite(norm)) FailLine(path, line, "the quaternion is too large to normalise");
  for (double& v : q) v /= norm;
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return Eigen::Vector3d(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)).normalized();
}

void CheckPosition(const fs::path& path, std::size_t line, const std::array<double, 3>& p) {
  for (const double v : p) {
    if (std::abs(v) > kMaxPoseTranslation_m) FailLine(path, line, "a position is outside [-1e9, 1e9] m");
  }
}

TimedTrajectory FromPoses(const fs::path& path, const std::vector<Pose>& poses, const std::vector<std::size_t>& lines) {
  if (poses.size() < 2) Fail(path, "expected at least 2 poses, got " + std::to_string(poses.size()));
  const auto n = static_cast<Eigen::Index>(poses.size());
  TimedTrajectory out{Trajectory{Positions(n, 3), Headings(n, 3)}, {}};
  for (Eigen::Index i = 0; i < n; ++i) {
    const Pose& pose = poses[static_cast<std::size_t>(i)];
    const std::size_t line = lines[static_cast<std::size_t>(i)];
    if (i > 0 && !(pose.t > poses[static_cast<std::size_t>(i) - 1].t)) {
      FailLine(path, line, "timestamp is not after the previous pose's (timestamps must increase)");
    }
    CheckPosition(path, line, pose.p);
    out.trajectory.positions.row(i) << pose.p[0], pose.p[1], pose.p[2];
    out.trajectory.headings.row(i) = Forward(path, line, pose.q).transpose();
    out.times_s.push_back(pose.t - poses.front().t);
  }
  return out;
}

TimedTrajectory LoadTum(const fs::path& path) {
  std::vector<Pose> poses;
  std::vector<std::size_t> lines;
  const std::vector<std::string> text = ReadLines(path);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (Trim(text[i]).front() == '#') continue;
    const auto tokens = SplitWhitespace(text[i]);
    if (tokens.size() != 8) FailLine(path, i + 1, "expected 8 numbers (t x y z qx qy qz qw), got " + std::to_string(tokens.size()));
    double v[8];
    for (int k = 0; k < 8; ++k) v[k] = ParseNumber(path, i + 1, tokens[static_cast<std::size_t>(k)]);
    poses.push_back(Pose{v[0], {v[1], v[2], v[3]}, {v[7], v[4], v[5], v[6]}});
    lines.push_back(i + 1);
  }
  return FromPoses(path, poses, lines);
}

TimedTrajectory LoadCsv(const fs::path& path) {
  const std::vector<std::string> text = ReadLines(path);
  const auto header = SplitCommas(text[0]);
  const auto column = [&](std::initializer_list<std::string_view> names) {
    for (std::size_t i = 0; i < header.size(); ++i) {
      for (const std::string_view n : names) {
        if (Trim(header[i]) == n) return i;
      }
    }
    FailLine(path, 1, "the header has no column " + std::string(*names.begin()) +
                          " (expected timestamp_kf(ns) or timestamp_ns, x, y, z, qw, qx, qy, qz)");
  };
  const std::size_t t = column({"timestamp_kf(ns)", "timestamp_ns"});
  const std::array<std::size_t, 7> c = {column({"x"}),  column({"y"}),  column({"z"}), column({"qw"}),
                                        column({"qx"}), column({"qy"}), column({"qz"})};
  std::vector<Pose> poses;
  std::vector<std::size_t> lines;
  for (std::size_t i = 1; i < text.size(); ++i) {
    const auto f = SplitCommas(text[i]);
    if (f.size() != header.size()) {
      FailLine(path, i + 1, "expected " + std::to_string(header.size()) + " fields as the header, got " +
                                std::to_string(f.size()));
    }
    double v[7];
    for (std::size_t k = 0; k < 7; ++k) v[k] = ParseNumber(path, i + 1, f[c[k]]);
    poses.push_back(Pose{ParseNumber(path, i + 1, f[t]) * 1e-9, {v[0], v[1], v[2]}, {v[3], v[4], v[5], v[6]}});
    lines.push_back(i + 1);
  }
  return FromPoses(path, poses, lines);
}

TimedTrajectory LoadKitti(const TrajectorySource& s) {
  TimedTrajectory out{LoadKittiPoses(s.poses), {}};
  const auto n = static_cast<std::size_t>(out.trajectory.size());
  if (n < 2) Fail(s.poses, "expected at least 2 poses, got " + std::to_string(n));
  if (!s.times) {
    for (std::size_t i = 0; i < n; ++i) out.times_s.push_back(static_cast<double>(i) / s.fps);
    return out;
  }
  const std::vector<std::string> text = ReadLines(*s.times);
  if (text.size() != n) {
    Fail(*s.times, std::to_string(text.size()) + " times for the " + std::to_string(n) + " poses of " + s.poses.string());
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double t = ParseNumber(*s.times, i + 1, text[i]);
    if (i > 0 && !(t > out.times_s.back())) {
      FailLine(*s.times, i + 1, "timestamp is not after the previous pose's (timestamps must increase)");
    }
    out.times_s.push_back(t);
  }
  const double first = out.times_s.front();
  for (double& t : out.times_s) t -= first;
  return out;
}

}  // namespace

void TrajectorySource::Validate() const {
  const auto fail = [](const std::string& what) { throw std::invalid_argument(what); };
  if (format == TrajectoryFormat::kKitti) {
    if ((fps > 0) == times.has_value()) fail("format kitti: give fps or a times file, one of them");
    if (!times && !(fps > 0 && fps <= 1000)) fail("fps: must be in (0, 1000], got " + std::to_string(fps));
  } else if (fps != 0 || times) {
    fail("fps and times apply to format kitti only (tum and csv files carry their times)");
  }
  if (!(start_s >= 0 && start_s <= 360'000'000.0)) fail("start: must be in [0s, 100000h]");
}

TimedTrajectory LoadRobotTrajectory(const TrajectorySource& source) {
  source.Validate();
  switch (source.format) {
    case TrajectoryFormat::kKitti: return LoadKitti(source);
    case TrajectoryFormat::kTum: return LoadTum(source.poses);
    case TrajectoryFormat::kCsv: return LoadCsv(source.poses);
  }
  throw std::invalid_argument("unknown trajectory format");
}

void CheckOneWorldFrame(const std::vector<TrajectorySource>& sources) {
  for (std::size_t i = 1; i < sources.size(); ++i) {
    if (sources[i].frame != sources[0].frame) {
      throw std::invalid_argument("trajectories[" + std::to_string(i) + "].frame: '" + sources[i].frame +
                                  "' differs from trajectories[0]'s '" + sources[0].frame +
                                  "': every robot's poses must lie in one world frame (dvpr does not transform "
                                  "between frames)");
    }
  }
}

}  // namespace dvpr
