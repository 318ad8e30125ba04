// One robot's trajectory from a KITTI, TUM or CSV file (robot_trajectory.h).
#include "experiments/domain/data/robot_trajectory.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "experiments/domain/data/loaders.h"
#include "experiments/domain/data/printable.h"
#include "experiments/domain/data/text_file.h"

namespace dvpr {

namespace fs = std::filesystem;
namespace tf = text_file;  // the text readers shared by loaders.cpp and robot_trajectory.cpp

namespace {

// The longest a trajectory may last, as a robot's start (TrajectorySource::Validate): start plus
// the time since the first pose stays far inside int64 nanoseconds on the team's clock.
constexpr double kMaxSpan_s = 360'000'000.0;
const char* const kSpanProblem = "timestamp is out of range: more than 360000000 s (100000 h) after the first pose's";

struct Pose {
  double t;
  std::array<double, 3> p;
  std::array<double, 4> q;  // w, x, y, z
};

// The camera's forward axis R(q) (0, 0, 1) of the normalised quaternion.
Eigen::Vector3d Forward(const fs::path& path, std::size_t line, std::array<double, 4> q) {
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(norm > 1e-9)) tf::FailLine(path, line, "the quaternion is zero (no rotation)");
  if (!std::isfinite(norm)) tf::FailLine(path, line, "the quaternion is too large to normalise");
  for (double& v : q) v /= norm;
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return Eigen::Vector3d(2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)).normalized();
}

void CheckPosition(const fs::path& path, std::size_t line, const std::array<double, 3>& p) {
  for (const double v : p) {
    if (std::abs(v) > kMaxPoseTranslation_m) tf::FailLine(path, line, "a position is outside [-1e9, 1e9] m");
  }
}

TimedTrajectory FromPoses(const fs::path& path, const std::vector<Pose>& poses, const std::vector<std::size_t>& lines) {
  if (poses.size() < 2) tf::Fail(path, "expected at least 2 poses, got " + std::to_string(poses.size()));
  const auto n = static_cast<Eigen::Index>(poses.size());
  TimedTrajectory out{Trajectory{Positions(n, 3), Headings(n, 3)}, {}};
  for (Eigen::Index i = 0; i < n; ++i) {
    const Pose& pose = poses[static_cast<std::size_t>(i)];
    const std::size_t line = lines[static_cast<std::size_t>(i)];
    if (i > 0 && !(pose.t > poses[static_cast<std::size_t>(i) - 1].t)) {
      tf::FailLine(path, line, "timestamp is not after the previous pose's (timestamps must increase)");
    }
    if (!(pose.t - poses.front().t <= kMaxSpan_s)) tf::FailLine(path, line, kSpanProblem);
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
  const std::vector<std::string> text = tf::ReadLines(path);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (tf::Trim(text[i]).front() == '#') continue;
    const auto tokens = tf::SplitWhitespace(text[i]);
    if (tokens.size() != 8) tf::FailLine(path, i + 1, "expected 8 numbers (t x y z qx qy qz qw), got " + std::to_string(tokens.size()));
    double v[8];
    for (int k = 0; k < 8; ++k) v[k] = tf::ParseNumber(path, i + 1, tokens[static_cast<std::size_t>(k)]);
    poses.push_back(Pose{v[0], {v[1], v[2], v[3]}, {v[7], v[4], v[5], v[6]}});
    lines.push_back(i + 1);
  }
  return FromPoses(path, poses, lines);
}

// `token`, a time in seconds, as nanoseconds in digits ("1317643200.5" -> "1317643200500000000"),
// or "" when it is not plain decimal digits of at most 9 decimals or does not fit int64.
std::string SecondsAsNanos(std::string_view token) {
  const std::size_t dot = token.find('.');
  const std::string_view whole = token.substr(0, dot);
  const std::string_view frac = dot == std::string_view::npos ? std::string_view() : token.substr(dot + 1);
  const auto digits = [](std::string_view d) { return d.find_first_not_of("0123456789") == std::string_view::npos; };
  if (whole.empty() || frac.size() > 9 || !digits(whole) || !digits(frac)) return "";
  std::string ns = std::string(whole) + std::string(frac) + std::string(9 - frac.size(), '0');
  ns.erase(0, std::min(ns.find_first_not_of('0'), ns.size() - 1));
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(ns.data(), ns.data() + ns.size(), v);
  return ec == std::errc() ? ns : "";
}

// A time in nanoseconds (Kimera-Multi's timestamp_kf(ns), timestamp_ns): a whole number in digits
// in [0, 2^63 - 1]. A number in another form is refused with what it would be as seconds.
std::int64_t ParseNanos(const fs::path& path, std::size_t line, const std::string& column, std::string_view token) {
  token = tf::Trim(token);
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  std::int64_t ns = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), ns);
  const bool whole = !token.empty() && end == token.data() + token.size();
  if (whole && (ec == std::errc::result_out_of_range || (ec == std::errc() && ns < 0))) {
    tf::FailLine(path, line, column + ": " + Printable(token, 40) +
                             " is out of range (nanoseconds must be a whole number in [0, 9223372036854775807])");
  }
  if (whole && ec == std::errc()) return ns;
  tf::ParseNumber(path, line, token);  // not a number, NaN or Inf: said as for every other column
  const std::string as_nanos = SecondsAsNanos(token);
  tf::FailLine(path, line, column + ": expected a whole number of nanoseconds, got '" + Printable(token, 40) + "'" +
                           (as_nanos.empty() ? "" : " (seconds? " + std::string(token) + " s is " + as_nanos + " ns)"));
}

// Nanosecond timestamps less than 1 us apart on average (a camera faster than 1 MHz) are times in
// seconds or milliseconds written where nanoseconds were meant.
void CheckNanosLookLikeNanos(const fs::path& path, const std::string& column, const std::vector<std::int64_t>& ns,
                             const std::vector<std::size_t>& lines, std::string_view first_token) {
  const auto gaps = static_cast<std::int64_t>(ns.size() - 1);
  if (ns.back() - ns.front() >= 1000 * gaps) return;
  const std::string as_nanos = SecondsAsNanos(tf::Trim(first_token));
  tf::FailLine(path, lines.back(),
           column + ": " + std::to_string(ns.size()) + " poses in " + std::to_string(ns.back() - ns.front()) +
               " ns, less than 1 us apart on average: seconds or milliseconds where nanoseconds were meant?" +
               (as_nanos.empty() || as_nanos == "0" ? std::string()
                                 : " As seconds, line " + std::to_string(lines.front()) + "'s " +
                                       std::string(tf::Trim(first_token)) + " is " + as_nanos + " ns"));
}

TimedTrajectory LoadCsv(const fs::path& path) {
  const std::vector<std::string> text = tf::ReadLines(path);
  const auto header = tf::SplitCommas(text[0]);
  const auto column = [&](std::initializer_list<std::string_view> names) {
    for (std::size_t i = 0; i < header.size(); ++i) {
      for (const std::string_view n : names) {
        if (tf::Trim(header[i]) == n) return i;
      }
    }
    tf::FailLine(path, 1, "the header has no column " + std::string(*names.begin()) +
                          " (expected timestamp_kf(ns) or timestamp_ns, x, y, z, qw, qx, qy, qz)");
  };
  const std::size_t t = column({"timestamp_kf(ns)", "timestamp_ns"});
  const std::array<std::size_t, 7> c = {column({"x"}),  column({"y"}),  column({"z"}), column({"qw"}),
                                        column({"qx"}), column({"qy"}), column({"qz"})};
  const std::string t_name(tf::Trim(header[t]));
  std::vector<Pose> poses;
  std::vector<std::size_t> lines;
  std::vector<std::int64_t> ns;
  for (std::size_t i = 1; i < text.size(); ++i) {
    const auto f = tf::SplitCommas(text[i]);
    if (f.size() != header.size()) {
      tf::FailLine(path, i + 1, "expected " + std::to_string(header.size()) + " fields as the header, got " +
                                std::to_string(f.size()));
    }
    double v[7];
    for (std::size_t k = 0; k < 7; ++k) v[k] = tf::ParseNumber(path, i + 1, f[c[k]]);
    ns.push_back(ParseNanos(path, i + 1, t_name, f[t]));
    // Times since the first pose, from exact integer differences (a double of 1.6e18 ns would
    // keep only about 256 ns).
    poses.push_back(Pose{static_cast<double>(ns.back() - ns.front()) / 1e9, {v[0], v[1], v[2]}, {v[3], v[4], v[5], v[6]}});
    lines.push_back(i + 1);
  }
  TimedTrajectory out = FromPoses(path, poses, lines);
  CheckNanosLookLikeNanos(path, t_name, ns, lines, tf::SplitCommas(text[1])[t]);
  return out;
}

TimedTrajectory LoadKitti(const TrajectorySource& s) {
  TimedTrajectory out{LoadKittiPoses(s.poses), {}};
  const auto n = static_cast<std::size_t>(out.trajectory.size());
  if (n < 2) tf::Fail(s.poses, "expected at least 2 poses, got " + std::to_string(n));
  if (!s.times) {
    for (std::size_t i = 0; i < n; ++i) out.times_s.push_back(static_cast<double>(i) / s.fps);
    return out;
  }
  const std::vector<std::string> text = tf::ReadLines(*s.times);
  if (text.size() != n) {
    tf::Fail(*s.times, std::to_string(text.size()) + " times for the " + std::to_string(n) + " poses of " + s.poses.string());
  }
  for (std::size_t i = 0; i < n; ++i) {
    const double t = tf::ParseNumber(*s.times, i + 1, text[i]);
    if (i > 0 && !(t > out.times_s.back())) {
      tf::FailLine(*s.times, i + 1, "timestamp is not after the previous pose's (timestamps must increase)");
    }
    if (i > 0 && !(t - out.times_s.front() <= kMaxSpan_s)) tf::FailLine(*s.times, i + 1, kSpanProblem);
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
