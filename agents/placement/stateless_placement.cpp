#include "agents/placement/stateless_placement.h"

#include "agents/algorithms/descriptor_index.h"

namespace dvpr {

void StatelessPlacement::Start(const AgentContext& robot) {
  self_ = robot.self;
  store_ = &robot.store;
}

QueryPlan StatelessPlacement::Plan(const float* descriptor) const {
  return PlanOf(strategy_.Route(self_, descriptor), self_, strategy_.UsesBroadcastChannel());
}

void StatelessPlacement::Store(RobotId querier, FrameId frame, const float* descriptor) {
  store_->Add(querier, frame, descriptor);
}

}  // namespace dvpr
