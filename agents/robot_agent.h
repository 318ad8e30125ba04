#pragma once
// One robot of the team: takes a frame every 1/fps, routes its descriptor as a
// query, serves the queries routed to it one at a time (search, store, reply),
// and follows a good match with a geometric-verification exchange with the
// robot that observed the matched frame (docs/design.md sections 1 and 3).
//
// What every robot does (frame clock, task queue, replies, verification, dropout) is
// AgentCore's and TaskServer's; this class keeps what the descriptor method adds: a frame's
// query is its global descriptor, routed by the placement component, and the answers combine into
// the nearest match. The agent only records what happened (QueryRecord, RobotLoad); metrics are
// computed elsewhere from those records. It talks only through Transport, so
// the same code runs in virtual time and as a real LCM process. Where its
// frames go and how it keeps what it stores is its placement component's
// (AgentPlacement), which may keep per-robot state and messages of its own.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "agents/agent_core.h"
#include "agents/algorithms/descriptor_index.h"
#include "agents/messages/channels.h"
#include "agents/messages/decoded_messages.h"
#include "agents/messages/transport.h"
#include "agents/placement/agent_placement.h"
#include "agents/task_server.h"

namespace dvpr {

// What a queued search of a descriptor holds.
struct DescriptorSearch {
  // The query's descriptor, in `message` when received, else the robot's own frame
  // (frames.descriptors, alive as long as the agent). Held, not copied: the 99 robots that queue
  // one broadcast query point at one decoded descriptor.
  const float* descriptor = nullptr;
  MessageRef<query_t> message;
  // Its result, if searched ahead; valid while index.changes() + 1 == searched_at.
  IndexSearchResult result;
  std::uint64_t searched_at = 0;  // 0: not searched
};

class RobotAgent final : public TaskServer<DescriptorSearch> {
 public:
  // `setup.frames.descriptors` holds the descriptors of every frame of the sequence; `placement`
  // is this robot's component (TeamPlacement::MakeAgentPlacement).
  RobotAgent(const AgentSetup& setup, Transport& transport, std::unique_ptr<AgentPlacement> placement,
             GeometricVerifier verifier);

  // Subscribes to the robot's channels, starts its placement component and schedules its first
  // frame at t = 0.
  void Start() override;
  // The channels Start() subscribes to (a real agent holds them from before its start barrier:
  // LcmTransport::HoldUntilSubscribed).
  static std::vector<std::string> InboxChannels(RobotId id);
  std::vector<std::string> Inbox() const override { return InboxChannels(id_); }

  std::vector<LostRobot> Lost() const override { return placement_->Lost(); }
  std::vector<IndexEntry> WholeFramesStored() const override { return index_.entries(); }
  const IncrementalIndex& index() const { return index_; }
  const AgentPlacement& placement() const { return *placement_; }

 private:
  void TakeFrame(int k) override;
  std::span<const float> VerificationFeatures(FrameId frame) override;
  std::int64_t Stored() const override { return static_cast<std::int64_t>(index_.size()); }
  void Stopped() override { placement_->Stop(); }
  std::int64_t Search(Task& task) override;
  void Searched(const Task& task) override;

  void PublishQuery(int k, const QueryPlan& plan);
  // Searches the task in service and the searches queued behind it up to the first that will
  // store (which changes the store before the next is served): the store is read once for all
  // of them while it is in cache, not once per service among 99 other robots' searches.
  void SearchAhead();
  void OnQuery(const MessageRef<query_t>& q, QueryRole role);
  void OnMatch(const match_t& m);
  // Keeps the nearest match; ties keep the earlier reply.
  void RecordReply(FrameId frame, RobotId responder, const std::optional<IndexMatch>& match);
  const float* DescriptorOf(FrameId frame) const { return descriptors_->row(frame.value).data(); }

  std::optional<IndexMatch> service_best_;  // its search's result, sent when the service ends
  const DescriptorMatrix* descriptors_;
  IncrementalIndex index_;
  std::unique_ptr<AgentPlacement> placement_;
  std::vector<std::uint32_t> match_channels_;  // by robot id (ChannelOf)
};

}  // namespace dvpr
