#pragma once
// The routing component of a robot whose strategy keeps no per-robot state (the paper's
// method, broadcast, probing, boundary replication, the load-balanced tables): it asks the
// team's shared RoutingStrategy and keeps what it is told to store in the robot's own store.
#include "agents/routing/agent_routing.h"
#include "agents/routing/routing.h"

namespace dvpr {

class StatelessRouting final : public AgentRouting {
 public:
  explicit StatelessRouting(const RoutingStrategy& strategy) : strategy_(strategy) {}

  void Start(const AgentContext& robot) override;
  void Stop() override {}
  QueryPlan Plan(const float* descriptor) const override;
  void Store(RobotId querier, FrameId frame, const float* descriptor) override;

 private:
  const RoutingStrategy& strategy_;
  RobotId self_;
  IncrementalIndex* store_ = nullptr;
};

}  // namespace dvpr
