#include "agents/recluster/recluster_placement.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "agents/recluster/recluster_agent.h"

namespace dvpr {

void ReclusterPlan::Validate() const {
  auto fail = [](const std::string& what) { throw std::invalid_argument("re-clustering plan: " + what); };
  params.Validate();
  if (!initial) fail("no initial table");
  if (static_cast<int>(stream_first.size()) != initial->num_robots()) {
    fail("stream_first has " + std::to_string(stream_first.size()) + " robots, the table " +
         std::to_string(initial->num_robots()));
  }
  if (epochs < 0) fail("epochs must be >= 0");
  if (leader.value < 0 || leader.value >= initial->num_robots()) fail("leader is not a robot of the team");
  if (sample_timeout < SimTime::Zero()) fail("sample_timeout must be >= 0");
}

ReclusterPlacement::ReclusterPlacement(ReclusterPlan plan)
    : TeamPlacement(plan.initial ? plan.initial->num_robots() : 1), plan_(std::move(plan)) {
  plan_.Validate();
}

std::unique_ptr<AgentPlacement> ReclusterPlacement::MakeAgentPlacement() const {
  return std::make_unique<ReclusterAgentPlacement>(plan_);
}

}  // namespace dvpr
