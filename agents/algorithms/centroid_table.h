#pragma once
// The centroid-to-robot table of the decentralized method (docs/design.md section 1): k centroids
// of descriptor space, each owned by one robot; a descriptor is routed to the owner of its nearest
// centroid. The paper gives each robot one centroid; the table allows any number per robot.
#include <vector>

#include "agents/algorithms/descriptors.h"
#include "agents/algorithms/half_screen.h"
#include "agents/algorithms/ids.h"

namespace dvpr {

class CentroidTable {
 public:
  // Centroid c is owned by owners[c]. Throws std::invalid_argument if the sizes differ, there
  // are no centroids, num_robots < 1, an owner is outside [0, num_robots), or a value is not
  // finite. A robot may own no centroid (it then receives no query).
  CentroidTable(CentroidMatrix centroids, std::vector<RobotId> owners, int num_robots);

  // The paper's table: k = num_robots x clusters_per_robot centroids, centroid c owned by robot
  // c mod num_robots (round robin, so with one cluster per robot centroid c belongs to robot c).
  static CentroidTable RoundRobin(CentroidMatrix centroids, int num_robots);

  int num_robots() const { return num_robots_; }
  int num_centroids() const { return static_cast<int>(owners_.size()); }
  Eigen::Index dim() const { return centroids_.cols(); }
  const CentroidMatrix& centroids() const { return centroids_; }

  RobotId OwnerOf(int centroid) const;                          // throws std::out_of_range
  const std::vector<int>& CentroidsOf(RobotId robot) const;     // ascending; throws out_of_range

  // Nearest centroid of a descriptor of dim() floats, exact (double), ties to the lowest index.
  int NearestCentroidOf(const float* descriptor) const;
  // The robot a descriptor is routed to: the owner of its nearest centroid.
  RobotId RouteOf(const float* descriptor) const { return OwnerOf(NearestCentroidOf(descriptor)); }
  RobotId RouteOf(DescriptorRow descriptor) const;

  // RouteOf for every row (float GEMM screening with exact tie-breaking, agents/algorithms/l2.h).
  std::vector<RobotId> RouteAll(const DescriptorMatrix& descriptors) const;

 private:
  CentroidMatrix centroids_;
  HalfScreen screen_;  // the centroids in half precision: NearestCentroidOf's lower bounds
  std::vector<RobotId> owners_;
  std::vector<std::vector<int>> by_robot_;
  int num_robots_;
};

}  // namespace dvpr
