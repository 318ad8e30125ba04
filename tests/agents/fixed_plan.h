#pragma once
// A routing component for agent tests: the same plan for every frame, stores into the robot's
// own index.
#include <utility>

#include "agents/algorithms/descriptor_index.h"
#include "agents/placement/agent_placement.h"

namespace dvpr::testing_support {

class FixedPlan final : public AgentPlacement {
 public:
  explicit FixedPlan(QueryPlan plan) : plan_(std::move(plan)) {}
  void Start(const AgentContext& robot) override { store_ = &robot.store; }
  void Stop() override {}
  QueryPlan Plan(const float*) const override { return plan_; }
  void Store(RobotId querier, FrameId frame, const float* descriptor) override { store_->Add(querier, frame, descriptor); }

 private:
  QueryPlan plan_;
  IncrementalIndex* store_ = nullptr;
};

}  // namespace dvpr::testing_support
