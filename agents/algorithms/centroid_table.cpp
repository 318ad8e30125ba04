#include "agents/algorithms/centroid_table.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "agents/algorithms/l2.h"

namespace dvpr {
namespace {

// The index of the smallest of values[0, count), the first of equals; 0 if all are NaN. Eight
// lanes side by side (GNU vectors), so the compiler need not keep one running minimum.
std::size_t ArgMin(const float* values, std::size_t count) {
  using Lanes = float __attribute__((vector_size(8 * sizeof(float))));
  using Indices = std::int32_t __attribute__((vector_size(8 * sizeof(std::int32_t))));
  constexpr std::size_t kLanes = 8;
  const float inf = std::numeric_limits<float>::infinity();
  Lanes min = {inf, inf, inf, inf, inf, inf, inf, inf};
  Indices at = {0, 1, 2, 3, 4, 5, 6, 7};
  Indices next = at;
  std::size_t i = 0;
  for (; i + kLanes <= count; i += kLanes) {
    Lanes v;
    std::memcpy(&v, values + i, sizeof v);
    const Indices smaller = v < min;  // strict: a lane keeps its first minimum
    min = smaller ? v : min;
    at = smaller ? next : at;
    next += static_cast<std::int32_t>(kLanes);
  }
  std::size_t best = 0;
  float best_value = inf;
  for (std::size_t l = 0; l < kLanes; ++l) {
    const auto index = static_cast<std::size_t>(at[l]);
    if (min[l] < best_value || (min[l] == best_value && index < best)) best = index, best_value = min[l];
  }
  for (; i < count; ++i) {
    if (values[i] < best_value) best = i, best_value = values[i];
  }
  return best;
}

}  // namespace

CentroidTable::CentroidTable(CentroidMatrix centroids, std::vector<RobotId> owners, int num_robots)
    : centroids_(std::move(centroids)),
      screen_(static_cast<int>(centroids_.cols())),
      owners_(std::move(owners)),
      num_robots_(num_robots) {
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
  for (Eigen::Index c = 0; c < centroids_.rows(); ++c) screen_.Append(centroids_.row(c).data());
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
  // Lower bounds from the half-precision screen (agents/algorithms/half_screen.h) rule out most centroids
  // from a few leading values; only the others get the exact distance, in double: the result is
  // the double scan's over all centroids. The first band's sums of every centroid come first, so
  // that the best exact distance the bounds test against starts at the likeliest winner.
  const auto k = static_cast<std::size_t>(num_centroids());
  const auto d = static_cast<int>(dim());
  std::vector<float> sums((k + HalfScreen::kTileRows - 1) / HalfScreen::kTileRows * HalfScreen::kTileRows);
  for (std::size_t first = 0; first < k; first += HalfScreen::kTileRows) {
    screen_.FirstBandSums(first, descriptor, sums.data() + first);
  }
  const std::size_t seed = ArgMin(sums.data(), k);
  std::size_t best = seed;
  double best_distance = ExactSquaredL2(descriptor, centroids_.row(static_cast<Eigen::Index>(seed)).data(), d);
  std::vector<float> limits(screen_.checks().size());
  const auto set_limits = [&] {
    for (std::size_t s = 0; s < limits.size(); ++s) limits[s] = screen_.Limit(best_distance, s);
  };
  set_limits();
  for (std::size_t first = 0; first < k; first += HalfScreen::kTileRows) {
    const unsigned alive = screen_.Survivors(first, descriptor, limits.data(), sums.data() + first);
    for (std::size_t c = first; c < std::min(k, first + HalfScreen::kTileRows); ++c) {
      if ((alive >> (c - first) & 1u) == 0 || c == seed) continue;
      const double distance = ExactSquaredL2(descriptor, centroids_.row(static_cast<Eigen::Index>(c)).data(), d);
      if (distance < best_distance || (distance == best_distance && c < best)) {  // ties to the lowest index
        best = c, best_distance = distance;
        set_limits();
      }
    }
  }
  return static_cast<int>(best);
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
