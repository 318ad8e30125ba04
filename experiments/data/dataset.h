#pragma once
// A deployment dataset: a trajectory and one descriptor per frame.
#include <string>

#include <Eigen/Core>

#include "agents/algorithms/descriptors.h"

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
  Eigen::Index size() const { return descriptors.rows(); }
  Eigen::Index dim() const { return descriptors.cols(); }
};

}  // namespace dvpr
