#include "agents/routing.h"

#include <algorithm>
#include <stdexcept>

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
  const auto send = [&](RobotId r, QueryRole role) {
    if (r == self || Contains(remote, r)) return;
    remote.push_back(r);
    if (!broadcast) {
      plan.channels.push_back(channels::QueryTo(r, role));
    } else if (role != QueryRole::kSearch) {
      throw std::logic_error("a broadcast query can only ask its receivers to search");
    }
  };
  for (RobotId r : decision.search_at) {
    send(r, Contains(decision.store_at, r) ? QueryRole::kSearchAndStore : QueryRole::kSearch);
  }
  for (RobotId r : decision.store_at) send(r, QueryRole::kStore);  // searchers were sent above
  if (broadcast && !remote.empty()) plan.channels.push_back(channels::kQueryAll);
  return plan;
}

std::unique_ptr<AgentRouting> RoutingStrategy::MakeAgentRouting() const {
  return std::make_unique<StatelessRouting>(*this);
}

}  // namespace dvpr
