#include "experiments/domain/data/team_plan.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "sim/random_bits.h"

namespace dvpr {

namespace {

constexpr std::array<std::string_view, 4> kScenarioNames{"split", "staggered", "reverse", "random_routes"};

// Appends rows of `from` (in `rows` order) to `to`, negating headings when backwards.
void AppendPoses(const Trajectory& from, const std::vector<std::int32_t>& rows, bool backwards, Trajectory& to) {
  const Eigen::Index first = to.positions.rows();
  const auto n = static_cast<Eigen::Index>(rows.size());
  to.positions.conservativeResize(first + n, Eigen::NoChange);
  to.headings.conservativeResize(first + n, Eigen::NoChange);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index row = rows[static_cast<std::size_t>(k)];
    to.positions.row(first + k) = from.positions.row(row);
    to.headings.row(first + k) = backwards ? Eigen::RowVector3d(-from.headings.row(row)) : from.headings.row(row);
  }
}

}  // namespace

std::string_view ToString(ScenarioKind kind) { return kScenarioNames[static_cast<std::size_t>(kind)]; }

ScenarioKind ParseScenarioKind(std::string_view name) {
  for (std::size_t i = 0; i < kScenarioNames.size(); ++i) {
    if (kScenarioNames[i] == name) return static_cast<ScenarioKind>(i);
  }
  throw std::invalid_argument("unknown scenario '" + std::string(name) +
                              "', expected split, staggered, reverse or random_routes");
}

void ScenarioSpec::Validate() const {
  const std::string kind_name(ToString(kind));
  if (!(std::isfinite(offset_s) && offset_s >= 0 && offset_s <= 360000000)) {
    throw std::invalid_argument("offset: expected a duration in [0 s, 100000 h]");
  }
  if (kind == ScenarioKind::kStaggered && offset_s <= 0) {
    throw std::invalid_argument("offset: staggered needs a positive offset (robot r starts r x offset later)");
  }
  if (offset_s > 0 && kind != ScenarioKind::kStaggered && kind != ScenarioKind::kReverse) {
    throw std::invalid_argument("offset: only staggered and reverse take an offset, not " + kind_name);
  }
  if (kind == ScenarioKind::kRandomRoutes && length < 2) {
    throw std::invalid_argument("length: random_routes needs each stretch's length in frames, at least 2");
  }
  if (kind != ScenarioKind::kRandomRoutes && length != 0) {
    throw std::invalid_argument("length: only random_routes takes a length, not " + kind_name);
  }
}

std::vector<RobotDrive> PlanDrives(const ScenarioSpec& spec, int frames, int robots, double fps) {
  spec.Validate();
  if (spec.kind == ScenarioKind::kSplit) throw std::invalid_argument("scenario split is the paper's split, not a team plan");
  if (robots < 1) throw std::invalid_argument("robots: at least 1, got " + std::to_string(robots));
  if (frames < 2) throw std::invalid_argument("a scenario needs at least 2 frames, got " + std::to_string(frames));
  if (spec.kind == ScenarioKind::kRandomRoutes && spec.length > frames) {
    throw std::invalid_argument("length: " + std::to_string(spec.length) + " frames, the sequence has " +
                                std::to_string(frames));
  }
  std::vector<RobotDrive> drives(static_cast<std::size_t>(robots));
  Xoshiro256 rng(MixSeed(spec.seed, 0x726f75746573ULL));  // "routes"
  for (int r = 0; r < robots; ++r) {
    RobotDrive& d = drives[static_cast<std::size_t>(r)];
    int first = 0, count = frames;
    if (spec.kind == ScenarioKind::kRandomRoutes) {
      count = spec.length;
      first = static_cast<int>(rng.Below(static_cast<std::uint64_t>(frames - count + 1)));
      // A start time uniform in [0, (N - length) / fps], to the nanosecond.
      const auto latest_ns = static_cast<std::uint64_t>(std::llround((frames - count) / fps * 1e9));
      d.start_s = static_cast<double>(rng.Below(latest_ns + 1)) * 1e-9;
    } else {
      d.start_s = r * spec.offset_s;
    }
    d.backwards = spec.kind == ScenarioKind::kReverse && r % 2 == 1;
    for (int k = 0; k < count; ++k) d.rows.push_back(d.backwards ? first + count - 1 - k : first + k);
  }
  return drives;
}

Dataset DriveTeam(const Trajectory& base, const std::vector<RobotDrive>& drives, double fps) {
  Dataset team;
  team.fps = fps;
  std::vector<std::vector<SimTime>> times;
  for (const RobotDrive& d : drives) {
    for (const std::int32_t row : d.rows) {
      if (row < 0 || row >= base.size()) {
        throw std::invalid_argument("a drive names row " + std::to_string(row) + " of a sequence of " +
                                    std::to_string(base.size()));
      }
    }
    AppendPoses(base, d.rows, d.backwards, team.trajectory);
    std::vector<SimTime>& t = times.emplace_back();
    for (std::size_t k = 0; k < d.rows.size(); ++k) t.push_back(SimTime::Seconds(d.start_s + static_cast<double>(k) / fps));
  }
  team.plan = PlannedSplit(times);
  return team;
}

Dataset TeamOfTrajectories(const std::vector<TrajectorySource>& sources,
                           const std::vector<TimedTrajectory>& trajectories, double fps) {
  if (sources.size() != trajectories.size()) {
    throw std::invalid_argument(std::to_string(sources.size()) + " trajectory sources, " +
                                std::to_string(trajectories.size()) + " trajectories");
  }
  CheckOneWorldFrame(sources);
  Dataset team;
  team.fps = fps;
  std::vector<std::vector<SimTime>> times;
  for (std::size_t r = 0; r < sources.size(); ++r) {
    const TimedTrajectory& tr = trajectories[r];
    std::vector<std::int32_t> rows(static_cast<std::size_t>(tr.trajectory.size()));
    for (std::size_t k = 0; k < rows.size(); ++k) rows[k] = static_cast<std::int32_t>(k);
    AppendPoses(tr.trajectory, rows, false, team.trajectory);
    std::vector<SimTime>& t = times.emplace_back();
    for (const double s : tr.times_s) t.push_back(SimTime::Seconds(sources[r].start_s + s));
  }
  team.plan = PlannedSplit(times);
  return team;
}

std::vector<double> TimesInFrames(const SequenceSplit& plan, double fps) {
  std::vector<double> frames;
  frames.reserve(plan.capture.size());
  for (const SimTime t : plan.capture) frames.push_back(t.ToSeconds() * fps);
  return frames;
}

}  // namespace dvpr
