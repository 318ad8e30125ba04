#pragma once
// Teams whose robots drive their own trajectories (issue 35; docs/design.md section 3, "Team
// plans"). The paper splits one drive among robots that all start at once (scenario `split`, the
// default). A team plan instead gives every robot its own poses and its own start on the team's
// common clock: from pose files (dataset.trajectories) or, on the shipped sequence, by a scenario:
//
//   staggered      every robot drives the whole sequence, robot r starting r x offset later;
//   reverse        every other robot (1, 3, ...) drives it backwards, facing the other way, robot
//                  r starting r x offset later (offset 0 by default: all at once);
//   random_routes  each robot a stretch of `length` consecutive frames from a uniformly drawn
//                  first frame, starting at a uniformly drawn time in [0, (N - length) / fps]
//                  (seeded by the scenario's own seed).
//
// The robots' rows are laid end to end in one Dataset (robot 0's first), Dataset::plan saying who
// drives which and when each is taken; all poses lie in one world frame.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "experiments/domain/data/dataset.h"
#include "experiments/domain/data/robot_trajectory.h"

namespace dvpr {

enum class ScenarioKind { kSplit, kStaggered, kReverse, kRandomRoutes };

// "split", "staggered", "reverse", "random_routes"; Parse throws std::invalid_argument listing them.
std::string_view ToString(ScenarioKind kind);
ScenarioKind ParseScenarioKind(std::string_view name);

struct ScenarioSpec {
  ScenarioKind kind = ScenarioKind::kSplit;
  double offset_s = 0;     // staggered (> 0) and reverse (>= 0): robot r starts r x offset later
  int length = 0;          // random_routes: frames of each robot's stretch, at least 2
  std::uint64_t seed = 1;  // random_routes
  // Throws std::invalid_argument "<field>: <problem>": staggered without a positive offset,
  // random_routes without a length, a field the kind does not take.
  void Validate() const;
  bool operator==(const ScenarioSpec&) const = default;
};

// One robot's drive over a sequence: the sequence's rows in driving order and when it starts.
struct RobotDrive {
  std::vector<std::int32_t> rows;
  bool backwards = false;  // driven in reverse: it faces the other way
  double start_s = 0;
};

// The drives of `robots` robots over a sequence of `frames` frames at `fps`. Throws
// std::invalid_argument for split (not a plan), fewer than 1 robot, a length above `frames`.
std::vector<RobotDrive> PlanDrives(const ScenarioSpec& spec, int frames, int robots, double fps);

// The team's poses: each drive's rows of `base` laid end to end (a backwards drive's headings
// negated), frame k of drive r taken at start_s + k / fps; Dataset::plan set, no descriptors yet.
Dataset DriveTeam(const Trajectory& base, const std::vector<RobotDrive>& drives, double fps);

// The team of dataset.trajectories: robot r's poses and times from its source, taken at
// sources[r].start_s + its own times; Dataset::plan set, no descriptors yet. Throws
// std::invalid_argument when the counts differ or the sources name different world frames.
Dataset TeamOfTrajectories(const std::vector<TrajectorySource>& sources,
                           const std::vector<TimedTrajectory>& trajectories, double fps);

// Each frame's capture time in frame periods (t x fps): the synthetic appearance model's clock,
// common to the team.
std::vector<double> TimesInFrames(const SequenceSplit& plan, double fps);

}  // namespace dvpr
