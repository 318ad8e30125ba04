#pragma once
// A deployment dataset: a trajectory and one descriptor per frame.
#include <optional>
#include <string>

#include <Eigen/Core>

#include "agents/algorithms/descriptors.h"
#include "experiments/domain/data/split.h"

namespace dvpr {

// One row per frame: x, y, z in metres (KITTI pose values 4, 8, 12).
using Positions = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
// One row per frame: the camera's forward direction (KITTI values 3, 7, 11), unit length.
using Headings = Positions;

struct Trajectory {
  Positions positions;
  Headings headings;
  Eigen::Index size() const { return positions.rows(); }
};

struct Dataset {
  std::string name;
  Trajectory trajectory;
  DescriptorMatrix descriptors;  // trajectory.size() x dim
  double fps = 10.0;
  // A planned team (dataset.trajectories, or a scenario other than split; docs/design.md section
  // 3): its robots' frames laid end to end and when each is taken. Empty: the paper's split.
  std::optional<SequenceSplit> plan = {};
  Eigen::Index size() const { return descriptors.rows(); }
  Eigen::Index dim() const { return descriptors.cols(); }
};

// How `robots` robots drive `data`: its plan (which must be for that many robots), else the
// paper's split (SplitSequence). Throws std::invalid_argument on a count the data cannot give.
SequenceSplit TeamSplit(const Dataset& data, int robots);

// The team of the first `robots` robots of a planned team: their poses, descriptors and plan (a
// prefix of the rows: robot 0's first). Throws std::invalid_argument when `team` has no plan or
// fewer robots.
Dataset FirstRobots(const Dataset& team, int robots);

// The suppression window of `frames` over `data`: within each robot's own stream for a plan.
inline FrameWindow SuppressionWindow(const Dataset& data, int frames) {
  return data.plan ? data.plan->Window(frames) : FrameWindow(frames);
}

}  // namespace dvpr
