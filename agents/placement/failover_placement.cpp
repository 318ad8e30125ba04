#include "agents/placement/failover_placement.h"

#include <algorithm>
#include <stdexcept>

#include <dvpr/agent_status_t.hpp>

#include "agents/algorithms/descriptor_index.h"
#include "agents/algorithms/frame_stream.h"
#include "agents/messages/team_sync.h"
#include "agents/placement/probe_placement.h"

namespace dvpr {

std::optional<RobotId> SuccessorOf(const CentroidTable& table, const std::vector<bool>& lost,
                                   const float* descriptor) {
  for (const auto& [distance, centroid] : RankCentroids(table, descriptor)) {
    const RobotId owner = table.OwnerOf(centroid);
    if (!lost.at(static_cast<std::size_t>(owner.value))) return owner;
  }
  return std::nullopt;
}

namespace {

// `robots` with each lost one replaced by `successor` (none: dropped), each robot once.
std::vector<RobotId> Replace(const std::vector<RobotId>& robots, const std::vector<bool>& lost,
                             const std::optional<RobotId>& successor) {
  std::vector<RobotId> out;
  for (RobotId r : robots) {
    const bool is_lost = lost.at(static_cast<std::size_t>(r.value));
    if (is_lost && !successor) continue;
    const RobotId to = is_lost ? *successor : r;
    if (std::find(out.begin(), out.end(), to) == out.end()) out.push_back(to);
  }
  return out;
}

}  // namespace

PlacementDecision FailOver(const PlacementDecision& decision, const CentroidTable* table, const std::vector<bool>& lost,
                         const float* descriptor) {
  const std::optional<RobotId> successor =
      table != nullptr ? SuccessorOf(*table, lost, descriptor) : std::optional<RobotId>();
  return PlacementDecision{Replace(decision.search_at, lost, successor), Replace(decision.store_at, lost, successor)};
}

FailoverTeam::FailoverTeam(std::unique_ptr<PlacementStrategy> inner, std::shared_ptr<const CentroidTable> table,
                           FailoverParams params, SimTime until)
    : TeamPlacement(inner->num_robots()), inner_(std::move(inner)), table_(std::move(table)), params_(params),
      until_(until) {
  params_.Validate();
}

std::unique_ptr<AgentPlacement> FailoverTeam::MakeAgentPlacement() const { return std::make_unique<FailoverPlacement>(*this); }

void FailoverTeam::UseProcessHeartbeats(std::int64_t team_key) {
  announce_ = false;
  team_key_ = team_key;
}

void FailoverPlacement::Start(const AgentContext& robot) {
  self_ = robot.self;
  transport_ = &robot.transport;
  store_ = &robot.store;
  frames_ = &robot.frames;
  online_ = true;
  const int n = team_.num_robots();
  detector_.emplace(self_, n, team_.params().timeout, transport_->Now());
  heartbeats_ = transport_->Subscribe<agent_status_t>(channels::kStatus, [this, n](const agent_status_t& s) {
    // Another team's heartbeats on the same group must not keep one of ours alive.
    if (!online_ || s.robots != n || s.team_key != team_.team_key()) return;
    detector_->Heard(RobotId(s.robot), transport_->Now());
  });
  Tick();
}

void FailoverPlacement::Stop() {
  online_ = false;
  heartbeats_.Reset();
}

// Announces (simulation), checks for silent robots, and comes back a period later until the
// team's last frame: after it no query is routed, so no detection would change anything.
void FailoverPlacement::Tick() {
  if (!online_) return;
  if (team_.announces()) Announce();
  detector_->Check(transport_->Now());
  if (transport_->Now() + team_.params().heartbeat_period <= team_.until()) {
    transport_->ScheduleAfter(team_.params().heartbeat_period, [this] { Tick(); });
  }
}

void FailoverPlacement::Announce() {
  const SimTime now = transport_->Now();
  agent_status_t s;
  s.utime = now.us();
  s.robot = static_cast<std::int16_t>(self_.value);
  s.robots = static_cast<std::int16_t>(team_.num_robots());
  s.team_key = team_.team_key();
  s.state = agent_status_t::RUNNING;
  s.ready_utime = 0;
  // Frames taken by now (frame k at k / fps), for whoever watches the heartbeats.
  const auto taken = static_cast<std::int64_t>(static_cast<double>(now.ns()) * frames_->fps / 1e9) + 1;
  s.frames_taken = static_cast<std::int32_t>(std::clamp<std::int64_t>(taken, 0, frames_->count));
  transport_->Publish(channels::kStatus, s);
}

QueryPlan FailoverPlacement::Plan(const float* descriptor) const {
  const PlacementStrategy& inner = team_.inner();
  PlacementDecision decision = inner.Route(self_, descriptor);
  if (!detector_->lost().empty()) decision = FailOver(decision, team_.table(), detector_->lost_flags(), descriptor);
  return PlanOf(decision, self_, inner.UsesBroadcastChannel());
}

void FailoverPlacement::Store(RobotId querier, FrameId frame, const float* descriptor) {
  store_->Add(querier, frame, descriptor);
}

std::vector<LostRobot> FailoverPlacement::Lost() const {
  return detector_ ? detector_->lost() : std::vector<LostRobot>{};
}

}  // namespace dvpr
