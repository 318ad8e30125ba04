#pragma once
// Failover (issue 14, docs/failover.md): when a robot is lost, the queries its clusters would
// have received go to a successor that every robot computes alike from what the whole team
// shares (the centroid table and the set of lost robots), with no message exchanged for it.
//
// The successor of a query whose owner is lost is the owner of the nearest centroid to the
// query among the centroids of live robots: the lost robot's clusters are divided among its
// neighbours in descriptor space exactly as if its centroids had been taken out of the table.
// That robot is also the one boundary replication (replicate_E) stored the nearest copies at,
// so a replica, where one was kept, is found where the queries now go. Broadcast has no table:
// a lost robot is just no longer searched.
//
// What the lost robot stored is gone; only copies other robots hold (replication) survive.
// Queries sent to it before it was declared lost wait in vain and count as lost.
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "agents/algorithms/centroid_table.h"
#include "agents/messages/transport.h"
#include "agents/placement/agent_placement.h"
#include "agents/placement/failure_detector.h"
#include "agents/placement/placement.h"

namespace dvpr {

// The owner of the nearest centroid to `descriptor` whose owner is not lost (lost: per robot);
// ties to the lowest centroid index. Empty when every owner is lost.
std::optional<RobotId> SuccessorOf(const CentroidTable& table, const std::vector<bool>& lost,
                                   const float* descriptor);

// `decision` with every lost robot replaced by SuccessorOf (dropped when there is no table or
// no successor), each robot kept once, at its first place.
PlacementDecision FailOver(const PlacementDecision& decision, const CentroidTable* table, const std::vector<bool>& lost,
                         const float* descriptor);

// A stateless strategy with failover: each robot's component (FailoverPlacement) listens to the
// heartbeats and routes around the robots it has declared lost.
class FailoverTeam final : public TeamPlacement {
 public:
  // `table`: the strategy's (null for broadcast). `until`: the team's last frame; heartbeats and
  // checks stop after it, so a simulation ends.
  FailoverTeam(std::unique_ptr<PlacementStrategy> inner, std::shared_ptr<const CentroidTable> table,
               FailoverParams params, SimTime until);

  std::string_view name() const override { return inner_->name(); }
  std::unique_ptr<AgentPlacement> MakeAgentPlacement() const override;

  // Real agents: the process already announces agent_status_t heartbeats with its team key, so
  // the components only listen, and only to heartbeats with that key.
  void UseProcessHeartbeats(std::int64_t team_key);

  const PlacementStrategy& inner() const { return *inner_; }
  const CentroidTable* table() const { return table_.get(); }
  const FailoverParams& params() const { return params_; }
  SimTime until() const { return until_; }
  bool announces() const { return announce_; }
  std::int64_t team_key() const { return team_key_; }

 private:
  std::unique_ptr<PlacementStrategy> inner_;
  std::shared_ptr<const CentroidTable> table_;
  FailoverParams params_;
  SimTime until_;
  bool announce_ = true;
  std::int64_t team_key_ = 0;
};

class FailoverPlacement final : public AgentPlacement {
 public:
  explicit FailoverPlacement(const FailoverTeam& team) : team_(team) {}

  void Start(const AgentContext& robot) override;
  void Stop() override;
  QueryPlan Plan(const float* descriptor) const override;
  void Store(RobotId querier, FrameId frame, const float* descriptor) override;
  std::vector<LostRobot> Lost() const override;

 private:
  void Tick();
  void Announce();

  const FailoverTeam& team_;
  RobotId self_;
  Transport* transport_ = nullptr;
  IncrementalIndex* store_ = nullptr;
  const FrameStream* frames_ = nullptr;
  std::optional<FailureDetector> detector_;
  bool online_ = false;
  Subscription heartbeats_;
};

}  // namespace dvpr
