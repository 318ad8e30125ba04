#pragma once
// The routing component of a robot whose strategy keeps no per-robot state (the paper's
// method, broadcast, probing, boundary replication, the load-balanced tables): it asks the
// team's shared PlacementStrategy and keeps what it is told to store in the robot's own store.
#include "agents/placement/agent_placement.h"
#include "agents/placement/placement.h"

namespace dvpr {

class StatelessPlacement final : public AgentPlacement {
 public:
  explicit StatelessPlacement(const PlacementStrategy& strategy) : strategy_(strategy) {}

  void Start(const AgentContext& robot) override;
  void Stop() override {}
  QueryPlan Plan(const float* descriptor) const override;
  void Store(RobotId querier, FrameId frame, const float* descriptor) override;

 private:
  const PlacementStrategy& strategy_;
  RobotId self_;
  IncrementalIndex* store_ = nullptr;
};

}  // namespace dvpr
