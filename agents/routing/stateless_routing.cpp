#include "agents/routing/stateless_routing.h"

#include "agents/algorithms/descriptor_index.h"

namespace dvpr {

void StatelessRouting::Start(const AgentContext& robot) {
  self_ = robot.self;
  store_ = &robot.store;
}

QueryPlan StatelessRouting::Plan(const float* descriptor) const {
  return PlanOf(strategy_.Route(self_, descriptor), self_, strategy_.UsesBroadcastChannel());
}

void StatelessRouting::Store(RobotId querier, FrameId frame, const float* descriptor) {
  store_->Add(querier, frame, descriptor);
}

}  // namespace dvpr
