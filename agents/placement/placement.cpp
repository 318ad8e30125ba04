#include "agents/placement/placement.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "agents/messages/channels.h"
#include "agents/placement/stateless_placement.h"

namespace dvpr {

namespace {

bool Contains(const std::vector<RobotId>& robots, RobotId r) {
  return std::find(robots.begin(), robots.end(), r) != robots.end();
}

}  // namespace

QueryPlan PlanOf(const PlacementDecision& decision, RobotId self, bool broadcast) {
  QueryPlan plan;
  plan.search_here = Contains(decision.search_at, self);
  plan.store_here = Contains(decision.store_at, self);
  plan.searches = static_cast<int>(decision.search_at.size());
  std::vector<RobotId> remote;
  std::int32_t max_id = self.value;
  for (const auto* robots : {&decision.search_at, &decision.store_at}) {
    for (RobotId r : *robots) {
      if (r.value < 0) throw std::logic_error("a routing decision named robot " + std::to_string(r.value));
      max_id = std::max(max_id, r.value);
    }
  }
  // By robot id: a robot named twice gets the query once (a bit per robot, not a search of
  // `remote`, which made a broadcast frame cost robots^2 / 2 comparisons).
  std::vector<bool> sent(static_cast<std::size_t>(max_id) + 1);
  const auto send = [&](RobotId r, QueryRole role) {
    if (r == self || sent[static_cast<std::size_t>(r.value)]) return;
    sent[static_cast<std::size_t>(r.value)] = true;
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

std::unique_ptr<AgentPlacement> PlacementStrategy::MakeAgentPlacement() const {
  return std::make_unique<StatelessPlacement>(*this);
}

}  // namespace dvpr
