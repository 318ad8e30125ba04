#pragma once
// One robot of the team: takes a frame every 1/fps, routes its descriptor as a
// query, serves the queries routed to it one at a time (search, store, reply),
// and follows a good match with a geometric-verification exchange with the
// robot that observed the matched frame (docs/design.md sections 1 and 3).
//
// The agent only records what happened (QueryRecord, RobotLoad); metrics are
// computed elsewhere from those records. It talks only through Transport, so
// the same code runs in virtual time and as a real LCM process. Where its
// frames go and how it keeps what it stores is its routing component's
// (AgentRouting), which may keep per-robot state and messages of its own.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "agents/agent_params.h"
#include "agents/agent_routing.h"
#include "agents/channels.h"
#include "agents/decoded_messages.h"
#include "agents/descriptor_index.h"
#include "agents/descriptors.h"
#include "agents/frame_stream.h"
#include "agents/geometric_verifier.h"
#include "agents/ids.h"
#include "agents/query_record.h"
#include "agents/reuse_queue.h"
#include "agents/robot_load.h"
#include "agents/team_agent.h"
#include "agents/transport.h"
#include "sim/sim_time.h"

namespace dvpr {

class RobotAgent final : public TeamAgent {
 public:
  // `routing` is this robot's component (TeamRouting::MakeAgentRouting).
  RobotAgent(RobotId id, const AgentParams& params, Transport& transport, std::unique_ptr<AgentRouting> routing,
             FrameStream frames, GeometricVerifier verifier);
  RobotAgent(const RobotAgent&) = delete;
  RobotAgent& operator=(const RobotAgent&) = delete;

  // Subscribes to the robot's channels, starts its routing component and schedules its first
  // frame at t = 0.
  void Start() override;
  // The channels Start() subscribes to (a real agent holds them from before its start barrier:
  // LcmTransport::HoldUntilSubscribed).
  static std::vector<std::string> InboxChannels(RobotId id);
  std::vector<std::string> Inbox() const override { return InboxChannels(id_); }
  // From now on the robot takes no frames and serves nothing (dropout).
  void GoOffline() override;

  RobotId id() const override { return id_; }
  // One record per frame of the stream, in order; a frame never taken (the robot went offline
  // first) is not Taken().
  const std::vector<QueryRecord>& outcomes() const override { return outcomes_; }
  RobotLoad load() const override;
  std::vector<LostRobot> Lost() const override { return routing_->Lost(); }
  const IncrementalIndex& index() const { return index_; }
  const AgentRouting& routing() const { return *routing_; }

 private:
  struct Task {
    enum class Kind { kSearch, kVerify } kind = Kind::kSearch;
    RobotId querier;
    FrameId frame;
    // kSearch: the query's descriptor, in `message` when received, else the robot's own frame
    // (frames_.descriptors, alive as long as the agent). Held, not copied: the 99 robots that
    // queue one broadcast query point at one decoded descriptor.
    const float* descriptor = nullptr;
    MessageRef<query_t> message;
    bool store = false;             // kSearch: keep the descriptor after searching
    // kSearch: its result, if searched ahead; valid while index_.changes() + 1 == searched_at.
    IndexSearchResult result;
    std::uint64_t searched_at = 0;  // 0: not searched
    FrameId match_frame;            // kVerify
    RobotId match_robot;
  };

  void TakeFrame(int k);
  void PublishQuery(int k, const QueryPlan& plan);
  // Queues a search of `descriptor` (in `message` if not empty, which the task keeps alive) or a
  // verification; nothing while offline.
  void EnqueueSearch(RobotId querier, FrameId frame, const float* descriptor, bool store,
                     MessageRef<query_t> message = {});
  void EnqueueVerify(RobotId querier, FrameId frame, FrameId match_frame);
  Task& PushTask(Task::Kind kind, RobotId querier, FrameId frame);
  // After PushTask: serves the task now if the robot was idle.
  void Enqueued();
  // Serves the queue's front task if the robot is idle.
  void StartNextTask();
  void Serve();  // in_service_
  // Service of in_service_: starts now, ends (Finish...) when its service time has elapsed. The
  // timer holds only the agent, so scheduling it does not allocate.
  void ServeSearch();
  // Searches the task in service and the searches queued behind it up to the first that will
  // store (which changes the store before the next is served): the store is read once for all
  // of them while it is in cache, not once per service among 99 other robots' searches.
  void SearchAhead();
  void FinishSearch();
  void ServeVerify();
  void FinishVerify();
  void EndService();
  // The channel name(robot) interned in `by_robot` (a slot per robot id, made on first use).
  PublishChannel ChannelOf(std::vector<std::uint32_t>& by_robot, RobotId robot, std::string (*name)(RobotId));
  void OnQuery(const MessageRef<query_t>& q, QueryRole role);
  void OnMatch(const match_t& m);
  void OnVerifyRequest(const verify_request_t& r);
  void OnVerifyResult(const verify_result_t& r);
  void RecordReply(FrameId frame, const std::optional<IndexMatch>& match);
  void MaybeVerify(int k);
  int LocalIndexOf(FrameId frame) const;

  // What every delivered query reads or writes comes first, together (a broadcast run reaches
  // each of 100 robots once a query, its state long gone from the nearer caches by then).
  RobotId id_;
  bool online_ = true;
  bool busy_ = false;
  AgentParams params_;
  Transport& transport_;
  RobotLoad load_;
  std::optional<IndexMatch> service_best_;  // its search's result, sent when the service ends
  Task in_service_;  // when busy_ (written by PushTask when idle, else swapped with the queue's front slot)
  ReuseQueue<Task> queue_;
  FrameStream frames_;
  GeometricVerifier verifier_;
  IncrementalIndex index_;
  std::unique_ptr<AgentRouting> routing_;
  std::vector<QueryRecord> outcomes_;
  // Reply and verification channels by robot id (kNoChannel until first used).
  static constexpr std::uint32_t kNoChannel = ~std::uint32_t{0};
  std::vector<std::uint32_t> match_channels_;
  std::vector<std::uint32_t> verify_request_channels_;
  std::vector<std::uint32_t> verify_result_channels_;
  verify_request_t verify_request_;
  std::vector<Subscription> subscriptions_;
};

}  // namespace dvpr
