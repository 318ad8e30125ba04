#include "agents/routing.h"

#include <algorithm>

#include "agents/channels.h"
#include "agents/stateless_routing.h"

namespace dvpr {

namespace {

bool Contains(const std::vector<RobotId>& robots, RobotId r) {
  return std::find(robots.begin(), robots.end(), r) != robots.end();
}

}  // namespace

QueryPlan PlanOf(const RoutingDecision& decision, RobotId self, bool broadcast) {
  QueryPlan plan;
  plan.search_here = Contains(decision.search_at, self);
  plan.store_here = Contains(decision.store_at, self);
  plan.searches = static_cast<int>(decision.search_at.size());
  std::vector<RobotId> remote;
  for (const auto* robots : {&decision.search_at, &decision.store_at}) {
    for (RobotId r : *robots) {
      if (r != self && !Contains(remote, r)) remote.push_back(r);
    }
  }
  if (remote.empty()) return plan;
  if (broadcast) {
    plan.channels.push_back(channels::kQueryAll);
    return plan;
  }
  for (RobotId r : remote) plan.channels.push_back(channels::Query(r));
  return plan;
}

std::unique_ptr<AgentRouting> RoutingStrategy::MakeAgentRouting() const {
  return std::make_unique<StatelessRouting>(*this);
}

}  // namespace dvpr
