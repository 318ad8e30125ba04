#pragma once
// What every robot of every method does, once: RobotAgent (global descriptors) and BowRobotAgent
// (bag-of-words) keep only how a frame becomes queries, how a query is served and how the
// answers combine (nearest match, vote).
//
// - The frame clock: frame k of the stream is taken at FrameStream::TimeOf(k) (TakeFrame).
// - The query records (QueryRecord): one per frame, begun when it is taken.
// - Reply collection, one rule for every method: a reply counts once per responder (a duplicate
//   is not a new responder), none after the last expected one, and a message naming a robot
//   outside the team is ignored and counted (RobotLoad::foreign_ids).
// - The verification exchange: a complete query whose best match is close enough is verified
//   with the robot that observed the match (itself: a task of its own queue).
// - Dropout: from GoOffline on the robot takes no frame and serves nothing; it keeps its
//   channels, so what others still send it is lost in the network (and counted there).
//
// The single-server task queue (SimPy's Resource) is agents/task_server.h, built on this.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "agents/agent_params.h"
#include "agents/algorithms/frame_stream.h"
#include "agents/algorithms/frame_window.h"
#include "agents/algorithms/geometric_verifier.h"
#include "agents/algorithms/ids.h"
#include "agents/algorithms/query_record.h"
#include "agents/algorithms/robot_load.h"
#include "agents/team_agent.h"
#include "agents/messages/transport.h"
#include "agents/messages/verify_messages.h"
#include "sim/sim_time.h"

namespace dvpr {

// Who a robot is and what it runs with, whatever its method.
struct AgentSetup {
  RobotId id;
  int robots = 0;  // team size: robot ids outside [0, robots) are foreign
  AgentParams params;
  FrameStream frames;
  // Where the team's streams begin (FrameWindow's stream_starts): empty for the paper's split,
  // each robot's first frame but robot 0's for a planned team, so a search's suppression window
  // stays inside the querying robot's own frames.
  std::vector<FrameId> window_streams = {};
  // Throws std::invalid_argument naming the field, prefixed with `agent` (the class's name).
  void Validate(const std::string& agent) const;
};

class AgentCore : public TeamAgent {
 public:
  AgentCore(const AgentCore&) = delete;
  AgentCore& operator=(const AgentCore&) = delete;

  void GoOffline() final;
  RobotId id() const final { return id_; }
  const std::vector<QueryRecord>& outcomes() const final { return records_->outcomes; }
  RobotLoad load() const final;

  // The channels of the verification exchange, which every agent's inbox holds.
  static std::vector<std::string> VerificationChannels(RobotId id);

 protected:
  // A complete query's best match at most verify_max_distance is verified (compared as a float,
  // as the distances are): verification.max_distance, or bow_max_distance for BoW's 1 - score.
  AgentCore(const AgentSetup& setup, double verify_max_distance, Transport& transport, GeometricVerifier verifier);

  // --- What the method does, called by the core.
  // Frame k of the stream is taken now (the robot is online): its record is begun with
  // BeginQuery and its queries are sent or queued.
  virtual void TakeFrame(int k) = 0;
  // The features a verification request carries for own frame `frame`
  // (agents/messages/verification_payload.h).
  virtual std::span<const float> VerificationFeatures(FrameId frame) = 0;
  // All replies of own frame k are in (its record's best is set by the method unless the method
  // sets it here: the vote): called before the best is verified.
  virtual void Conclude(int /*k*/) {}
  // What the robot stores, for RobotLoad::stored.
  virtual std::int64_t Stored() const = 0;
  // The queue: a verification task, and letting go of every waiting task (dropout).
  virtual void EnqueueVerify(RobotId querier, FrameId frame, FrameId match_frame) = 0;
  virtual void DropWaiting() = 0;
  // After GoOffline's own work: the method stops what it runs of its own.
  virtual void Stopped() {}

  // --- What the method calls.
  // Subscribes to the verification exchange's channels (in the order every agent did) and starts
  // the frame clock: the method's Start calls it after subscribing to its own channels.
  void SubscribeVerification();
  void StartClock();
  // Frame k's record, stamped as taken now and waiting for `expected_replies` replies.
  QueryRecord& BeginQuery(int k, int expected_replies);
  QueryRecord& Record(int k) { return records_->outcomes[static_cast<std::size_t>(k)]; }
  // Position of `frame` in this robot's stream, -1 if not one of its frames.
  int LocalIndexOf(FrameId frame) const;
  FrameId FrameAt(int k) const { return FrameId(records_->frames.first.value + k); }
  const FrameStream& frames() const { return records_->frames; }
  // True (and counted) when `robot` is not of the team.
  bool Foreign(int robot);
  // A reply's robot ids: false (counted) if the responder or, with a match, the robot that
  // observed the match is not of the team.
  bool ReplyFromTeam(int responder, bool has_match, int match_robot);
  // A reply from `responder` to own frame `frame`: its position k when it is the first reply of
  // this responder to a query still waiting, else -1 (not an own frame, late, or a duplicate).
  // The method records its answer, then calls Replied(k).
  int AcceptReply(FrameId frame, RobotId responder);
  // After an accepted reply: when it was the last, stamps the latency, concludes and verifies.
  void Replied(int k);
  // The verification of `querier`'s frame against own `match_frame` at the end of its service:
  // the verdict recorded (own query) or sent back.
  void FinishVerification(RobotId querier, FrameId frame, FrameId match_frame);
  // A channel named name(robot), interned once per robot in `by_robot`.
  PublishChannel ChannelOf(std::vector<std::uint32_t>& by_robot, RobotId robot, std::string (*name)(RobotId));
  void Keep(Subscription subscription) { records_->subscriptions.push_back(std::move(subscription)); }

  // What a delivered query reads or writes comes first, together (a broadcast run reaches each of
  // 100 robots once a query, its state long gone from the nearer caches by then); the derived
  // queue's fields follow these.
  RobotId id_;
  bool online_ = true;
  Transport& transport_;
  AgentParams params_;
  FrameWindow window_;  // params_.suppression_frames within the query's stream
  RobotLoad load_;

 private:
  void Tick(int k);
  void MaybeVerify(int k);
  void OnVerifyRequest(const verify_request_t& r);
  void OnVerifyResult(const verify_result_t& r);

  int robots_;
  float verify_max_distance_;
  // The rest, which a delivered query does not touch, held apart so the derived queue's fields
  // follow the hot ones above.
  struct Records {
    FrameStream frames;
    GeometricVerifier verifier;
    std::vector<QueryRecord> outcomes;
    // Per own frame while its replies come in: a bit per robot id that replied (empty otherwise).
    std::vector<std::vector<std::uint64_t>> responded;
    std::vector<std::uint32_t> verify_request_channels;  // by robot id (ChannelOf)
    std::vector<std::uint32_t> verify_result_channels;
    verify_request_t verify_request;  // reused: its payload buffer is refilled, not reallocated
    std::vector<Subscription> subscriptions;
  };
  std::unique_ptr<Records> records_;
  static constexpr std::uint32_t kNoChannel = ~std::uint32_t{0};
};

}  // namespace dvpr
