#pragma once
// Centroid-to-robot tables that balance the expected load (issue 8). The paper gives robot c
// centroid c; when the deployment occupies a small part of the space the training set covered,
// one robot then serves a large share of all queries. With several clusters per robot
// (k = c x n), the clusters can be packed onto robots by their expected load:
//
// - LPT (Graham's longest-processing-time greedy bin packing): clusters by decreasing expected
//   load, each to the currently least-loaded robot. Makespan within 4/3 of optimal.
// - Bounded loads (Mirrokni, Thorup, Zadimoghaddam, "Consistent hashing with bounded loads",
//   2018): each cluster prefers its round-robin robot (the paper's table); a cluster that would
//   lift that robot above (1 + epsilon) x the average expected load goes to the next robot in
//   ring order that has room (the least loaded if none has), so the table moves as few
//   clusters away from the paper's assignment as the bound allows.
//
// Expected loads: the number of sample descriptors nearest to each centroid. The sample is
// what the team shares at start (the experiments use every 20th deployment frame, or the
// training set's own cluster sizes); it costs no bytes during the run.
#include <vector>

#include "agents/algorithms/centroid_table.h"
#include "agents/algorithms/descriptors.h"

namespace dvpr {

struct LoadBalanceParams {
  // < 0: LPT; >= 0: bounded loads with capacity (1 + epsilon) x the average expected load.
  double epsilon = -1.0;
  void Validate() const;  // throws std::invalid_argument naming the field
  bool operator==(const LoadBalanceParams&) const = default;
};

// Per centroid: how many rows of `sample` have it as nearest centroid (ties to the lowest
// index), plus `prior` each, so that a centroid the sample misses still counts a little.
std::vector<double> ExpectedLoads(const CentroidMatrix& centroids, const DescriptorMatrix& sample,
                                  double prior = 0.0);

// Owner of each cluster given the clusters' expected loads (>= 0, finite). Deterministic: equal
// loads are taken in index order, equally loaded robots by lowest id.
std::vector<RobotId> AssignByLoad(const std::vector<double>& loads, int num_robots,
                                  const LoadBalanceParams& params);

// The table with those owners: ExpectedLoads on `sample`, then AssignByLoad.
CentroidTable LoadBalancedTable(CentroidMatrix centroids, const DescriptorMatrix& sample, int num_robots,
                                const LoadBalanceParams& params);

}  // namespace dvpr
