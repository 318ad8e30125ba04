#pragma once
// The paper's method: a query goes only to the robot that owns the nearest
// centroid, which searches what it stored, stores the query and replies.
#include <memory>

#include "agents/algorithms/centroid_table.h"
#include "agents/placement/placement.h"

namespace dvpr {

class DecentralizedPlacement final : public PlacementStrategy {
 public:
  explicit DecentralizedPlacement(std::shared_ptr<const CentroidTable> table)
      : PlacementStrategy(table->num_robots()), table_(std::move(table)) {}
  std::string_view name() const override { return "decentralized"; }
  const CentroidTable& table() const { return *table_; }

 private:
  void DoRoute(RobotId, const float* descriptor, PlacementDecision& out) const override {
    const RobotId owner = table_->RouteOf(descriptor);
    out.search_at.push_back(owner);
    out.store_at.push_back(owner);
  }
  std::shared_ptr<const CentroidTable> table_;
};

}  // namespace dvpr
