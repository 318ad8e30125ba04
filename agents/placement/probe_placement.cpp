#include "agents/placement/probe_placement.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dvpr {

std::vector<std::pair<double, int>> RankCentroids(const CentroidTable& table, const float* descriptor) {
  const auto& c = table.centroids();
  std::vector<std::pair<double, int>> ranked(static_cast<std::size_t>(c.rows()));
  for (Eigen::Index k = 0; k < c.rows(); ++k) {
    double d2 = 0.0;
    for (Eigen::Index j = 0; j < c.cols(); ++j) {
      const double diff = static_cast<double>(descriptor[j]) - static_cast<double>(c(k, j));
      d2 += diff * diff;
    }
    ranked[static_cast<std::size_t>(k)] = {std::sqrt(d2), static_cast<int>(k)};
  }
  std::sort(ranked.begin(), ranked.end());
  return ranked;
}

std::vector<RobotId> OwnersWithin(const CentroidTable& table, const float* descriptor, double epsilon,
                                  int max_centroids) {
  const auto ranked = RankCentroids(table, descriptor);
  // An infinite epsilon means no bound at all: (1 + inf) x 0 would be NaN when the descriptor
  // sits exactly on a centroid.
  const double limit = std::isinf(epsilon) ? INFINITY : ranked.front().first * (1.0 + epsilon);
  std::vector<RobotId> owners;
  const auto n = std::min<std::size_t>(ranked.size(), static_cast<std::size_t>(std::max(1, max_centroids)));
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && ranked[i].first > limit) break;
    const RobotId owner = table.OwnerOf(ranked[i].second);
    if (std::find(owners.begin(), owners.end(), owner) == owners.end()) owners.push_back(owner);
  }
  return owners;
}

void MultiProbeParams::Validate() const {
  if (probes < 1) throw std::invalid_argument("multi_probe.probes must be >= 1, got " + std::to_string(probes));
  if (std::isnan(epsilon)) throw std::invalid_argument("multi_probe.epsilon must be a number");
}

MultiProbePlacement::MultiProbePlacement(std::shared_ptr<const CentroidTable> table, MultiProbeParams params)
    : PlacementStrategy(table->num_robots()), table_(std::move(table)), params_(params) {
  params_.Validate();
}

void MultiProbePlacement::DoRoute(RobotId, const float* descriptor, PlacementDecision& out) const {
  const double epsilon = params_.epsilon < 0 ? INFINITY : params_.epsilon;
  out.search_at = OwnersWithin(*table_, descriptor, epsilon, params_.probes);
  out.store_at.push_back(out.search_at.front());
}

void ReplicationParams::Validate() const {
  if (!(epsilon >= 0.0)) throw std::invalid_argument("boundary_replication.epsilon must be >= 0");
  if (max_replicas < 1) {
    throw std::invalid_argument("boundary_replication.max_replicas must be >= 1, got " + std::to_string(max_replicas));
  }
}

BoundaryReplicationPlacement::BoundaryReplicationPlacement(std::shared_ptr<const CentroidTable> table,
                                                       ReplicationParams params)
    : PlacementStrategy(table->num_robots()), table_(std::move(table)), params_(params) {
  params_.Validate();
}

void BoundaryReplicationPlacement::DoRoute(RobotId, const float* descriptor, PlacementDecision& out) const {
  out.store_at = OwnersWithin(*table_, descriptor, params_.epsilon, params_.max_replicas);
  out.search_at.push_back(out.store_at.front());
}

}  // namespace dvpr
