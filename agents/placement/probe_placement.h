#pragma once
// Strategies that recover the recall the paper loses at cluster borders
// (issue 8), both over the same centroid table as the paper's method.
//
// MultiProbePlacement searches at the owners of several near centroids (FAISS
// nprobe; with epsilon, SPANN's adaptive query-aware pruning: only centroids
// within (1 + epsilon) times the nearest distance). The descriptor is stored
// once, at the nearest centroid's owner.
//
// BoundaryReplicationPlacement searches only at the nearest owner but stores the
// descriptor also at the owners of centroids within (1 + epsilon) of the
// nearest (SPANN's closure assignment of boundary points), so later queries
// from across the border find it.
#include <memory>
#include <utility>
#include <vector>

#include "agents/algorithms/centroid_table.h"
#include "agents/placement/placement.h"

namespace dvpr {

// Centroids ranked by L2 distance to the descriptor, nearest first; ties by
// index. Returns (distance, centroid) pairs.
std::vector<std::pair<double, int>> RankCentroids(const CentroidTable& table, const float* descriptor);

// Owners of the ranked centroids whose distance is at most (1 + epsilon)
// times the nearest one, capped at max_centroids centroids; no duplicates,
// nearest first. The nearest owner is always included.
std::vector<RobotId> OwnersWithin(const CentroidTable& table, const float* descriptor, double epsilon,
                                  int max_centroids);

struct MultiProbeParams {
  int probes = 2;          // at most this many centroids probed
  double epsilon = -1.0;   // < 0: always `probes` centroids; >= 0: only those within (1 + epsilon)
  void Validate() const;
  bool operator==(const MultiProbeParams&) const = default;
};

class MultiProbePlacement final : public PlacementStrategy {
 public:
  MultiProbePlacement(std::shared_ptr<const CentroidTable> table, MultiProbeParams params);
  std::string_view name() const override { return params_.epsilon < 0 ? "multi_probe" : "adaptive_probe"; }

 private:
  void DoRoute(RobotId self, const float* descriptor, PlacementDecision& out) const override;
  std::shared_ptr<const CentroidTable> table_;
  MultiProbeParams params_;
};

struct ReplicationParams {
  double epsilon = 0.1;    // replicate to owners of centroids within (1 + epsilon) of the nearest
  int max_replicas = 3;    // at most this many centroids (the nearest included)
  void Validate() const;
  bool operator==(const ReplicationParams&) const = default;
};

class BoundaryReplicationPlacement final : public PlacementStrategy {
 public:
  BoundaryReplicationPlacement(std::shared_ptr<const CentroidTable> table, ReplicationParams params);
  std::string_view name() const override { return "boundary_replication"; }

 private:
  void DoRoute(RobotId self, const float* descriptor, PlacementDecision& out) const override;
  std::shared_ptr<const CentroidTable> table_;
  ReplicationParams params_;
};

}  // namespace dvpr
