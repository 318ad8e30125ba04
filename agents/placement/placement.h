#pragma once
// Routing strategies: where a new frame's descriptor is searched and where it
// is stored. A strategy here is shared by the whole team and keeps no state of
// its own: a deterministic function of (querying robot, descriptor). Each
// agent routes through its own StatelessPlacement over it
// (agents/placement/stateless_placement.h), which also puts the decision on the wire: the
// channel each query goes on says what its receiver does with it.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "agents/algorithms/ids.h"
#include "agents/placement/agent_placement.h"

namespace dvpr {

struct PlacementDecision {
  std::vector<RobotId> search_at;  // robots that search their store and reply (self: locally)
  std::vector<RobotId> store_at;   // robots that keep the descriptor for later searches
};

// How `self` puts a decision on the wire: each remote robot once (searchers first, then the
// robots that only store, in the decision's order), on the query channel of its role
// (channels::QueryTo). With `broadcast`, one publication on channels::kQueryAll instead; every
// remote robot must then be a searcher that does not store (std::logic_error otherwise).
QueryPlan PlanOf(const PlacementDecision& decision, RobotId self, bool broadcast);

class PlacementStrategy : public TeamPlacement {
 public:
  PlacementDecision Route(RobotId self, const float* descriptor) const {
    PlacementDecision decision;
    DoRoute(self, descriptor, decision);
    return decision;
  }

  // True: the remote searches are one publication on the broadcast channel
  // (one transmission on a shared medium) instead of one unicast each.
  virtual bool UsesBroadcastChannel() const { return false; }

  // Every robot's component is a StatelessPlacement over this strategy.
  std::unique_ptr<AgentPlacement> MakeAgentPlacement() const final;

 protected:
  explicit PlacementStrategy(int num_robots) : TeamPlacement(num_robots) {}

 private:
  virtual void DoRoute(RobotId self, const float* descriptor, PlacementDecision& out) const = 0;
};

// The baseline: every robot keeps its own frames and every query is searched
// by all robots (the querying robot locally, the others over the network).
class BroadcastPlacement final : public PlacementStrategy {
 public:
  explicit BroadcastPlacement(int num_robots) : PlacementStrategy(num_robots) {}
  std::string_view name() const override { return "broadcast"; }
  bool UsesBroadcastChannel() const override { return true; }

 private:
  void DoRoute(RobotId self, const float*, PlacementDecision& out) const override {
    out.search_at.reserve(static_cast<std::size_t>(num_robots()));
    for (int r = 0; r < num_robots(); ++r) out.search_at.push_back(RobotId(r));
    out.store_at.push_back(self);
  }
};

}  // namespace dvpr
