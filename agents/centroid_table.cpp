#include "agents/centroid_table.h"

#include <limits>
#include <stdexcept>
#include <string>

#include "agents/l2.h"

namespace dvpr {

CentroidTable::CentroidTable(CentroidMatrix centroids, std::vector<RobotId> owners, int num_robots)
    : centroids_(std::move(centroids)), owners_(std::move(owners)), num_robots_(num_robots) {
  if (num_robots_ < 1) {
    throw std::invalid_argument("CentroidTable: num_robots must be >= 1, got " +
                                std::to_string(num_robots_));
  }
  if (centroids_.rows() == 0) throw std::invalid_argument("CentroidTable: no centroids");
  if (static_cast<std::size_t>(centroids_.rows()) != owners_.size()) {
    throw std::invalid_argument("CentroidTable: " + std::to_string(centroids_.rows()) +
                                " centroids but " + std::to_string(owners_.size()) + " owners");
  }
  if (!centroids_.allFinite()) throw std::invalid_argument("CentroidTable: non-finite centroid");
  centroid_norms_ = SquaredNorms(centroids_);
  max_centroid_norm_ = centroid_norms_.maxCoeff();
  by_robot_.resize(static_cast<std::size_t>(num_robots_));
  for (std::size_t c = 0; c < owners_.size(); ++c) {
    const int r = owners_[c].value;
    if (r < 0 || r >= num_robots_) {
      throw std::invalid_argument("CentroidTable: centroid " + std::to_string(c) + " owned by robot " +
                                  std::to_string(r) + ", outside [0, " +
                                  std::to_string(num_robots_) + ")");
    }
    by_robot_[static_cast<std::size_t>(r)].push_back(static_cast<int>(c));
  }
}

CentroidTable CentroidTable::RoundRobin(CentroidMatrix centroids, int num_robots) {
  if (num_robots < 1) {
    throw std::invalid_argument("CentroidTable: num_robots must be >= 1, got " +
                                std::to_string(num_robots));
  }
  std::vector<RobotId> owners;
  for (Eigen::Index c = 0; c < centroids.rows(); ++c) {
    owners.emplace_back(static_cast<std::int32_t>(c % num_robots));
  }
  return CentroidTable(std::move(centroids), std::move(owners), num_robots);
}

RobotId CentroidTable::OwnerOf(int centroid) const {
  if (centroid < 0 || centroid >= num_centroids()) {
    throw std::out_of_range("CentroidTable: no centroid " + std::to_string(centroid));
  }
  return owners_[static_cast<std::size_t>(centroid)];
}

const std::vector<int>& CentroidTable::CentroidsOf(RobotId robot) const {
  if (robot.value < 0 || robot.value >= num_robots_) {
    throw std::out_of_range("CentroidTable: no robot " + std::to_string(robot.value));
  }
  return by_robot_[static_cast<std::size_t>(robot.value)];
}

int CentroidTable::NearestCentroidOf(const float* descriptor) const {
  // Float distances screen (one matrix-vector product, as NearestRows); only the centroids
  // within twice the float error of the float minimum can be the exact nearest, and those are
  // decided in double: the result is the double scan's over all centroids, at a tenth its cost.
  const Eigen::Map<const Eigen::VectorXf> q(descriptor, dim());
  const float q_norm = q.squaredNorm();
  Eigen::VectorXf screen(num_centroids());
  screen.noalias() = centroids_ * q;
  screen = (centroid_norms_ - 2.0f * screen).array() + q_norm;
  const float limit = screen.minCoeff() + 2.0f * GemmErrorBound(q_norm, max_centroid_norm_, dim());
  int best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int c = 0; c < num_centroids(); ++c) {
    if (screen[c] > limit) continue;
    const double d = ExactSquaredL2(descriptor, centroids_.row(c).data(), dim());
    if (d < best_distance) best_distance = d, best = c;  // strict: ties to the lowest index
  }
  return best;
}

RobotId CentroidTable::RouteOf(DescriptorRow descriptor) const {
  if (descriptor.size() != dim()) {
    throw std::invalid_argument("CentroidTable::RouteOf: descriptor has " +
                                std::to_string(descriptor.size()) + " values, centroids " +
                                std::to_string(dim()));
  }
  return RouteOf(descriptor.data());
}

std::vector<RobotId> CentroidTable::RouteAll(const DescriptorMatrix& descriptors) const {
  const std::vector<int> nearest = NearestRows(descriptors, centroids_);
  std::vector<RobotId> routes;
  routes.reserve(nearest.size());
  for (int c : nearest) routes.push_back(owners_[static_cast<std::size_t>(c)]);
  return routes;
}

}  // namespace dvpr
