#pragma once
// One robot of a bag-of-words team (docs/bow.md): the distributed inverted index of Cieslewski
// and Scaramuzza (ICRA 2017) as messages. What every robot does (frame clock, FIFO task queue and
// service-time model, replies, verification exchange, dropout) is AgentCore's and TaskServer's,
// as for RobotAgent; this class keeps how a frame becomes parts, how a part is scored and how
// the answers vote.
//
// Per frame it takes, the robot splits its L1-normalised BoW vector by word owner
// (BowTeamPlan::words), publishes one bow_query_t to each other owner of a non-empty part
// (channels::BowQuery), scores its own part locally, and waits for the replies. A responder
// scores the part against what it stored (BowIndex), replies with its best frame, the robot that
// observed it and the partial score (bow_match_t on channels::BowMatch), then stores the part.
// With every reply in, the querying robot votes (Vote, agents/algorithms/bow_words.h; the answers in
// responder order, so the sum of the scores does not depend on arrival order), records the voted
// frame with distance 1 - the voters' summed partial scores, and verifies it as RobotAgent does
// when that distance is at most verification.bow_max_distance (1 - a score has another scale
// than max_distance's squared L2).
//
// bow_broadcast (BowTeamPlan::words null): the full vector to every other robot on
// channels::BowProbe; each scores it against its own frames and keeps nothing; the querying robot
// keeps its own frame. A frame without words is still a query: the robot searches its own store
// with the empty part (no match), so the record is taken and complete.
//
// Service time: params.service.fixed + per_comparison x the postings visited (the BoW
// counterpart of the descriptors compared; RobotLoad::comparisons counts them).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "agents/agent_core.h"
#include "agents/algorithms/bow_index.h"
#include "agents/algorithms/bow_vector.h"
#include "agents/algorithms/bow_words.h"
#include "agents/task_server.h"
#include "agents/messages/transport.h"

namespace dvpr {

// How a BoW team splits and sends its queries: the same for every robot of the team.
struct BowTeamPlan {
  int robots = 0;
  // Who owns each word (scores and keeps its share of every query); null: bow_broadcast.
  std::shared_ptr<const WordOwners> words;
  bool broadcast() const { return words == nullptr; }
};

// What a queued search of a part holds.
struct BowSearch {
  BowVector part;
};

class BowRobotAgent final : public TaskServer<BowSearch> {
 public:
  // `setup.frames` gives when the robot takes which frames (its descriptors are not used) and
  // setup.robots must be plan.robots; `vectors` holds every frame of the sequence (read when a
  // frame is taken and for the verification payload) and outlives the agent.
  BowRobotAgent(const AgentSetup& setup, Transport& transport, BowTeamPlan plan, const std::vector<BowVector>& vectors,
                GeometricVerifier verifier);

  void Start() override;
  static std::vector<std::string> InboxChannels(RobotId id);
  std::vector<std::string> Inbox() const override { return InboxChannels(id_); }

  const BowIndex& index() const { return index_; }

 private:
  void TakeFrame(int k) override;
  std::span<const float> VerificationFeatures(FrameId frame) override;
  void Conclude(int k) override;
  std::int64_t Stored() const override { return static_cast<std::int64_t>(index_.size()); }
  std::int64_t Search(Task& task) override;
  void Searched(const Task& task) override;

  void PublishParts(FrameId frame, const std::vector<BowVector>& parts, bool broadcast, const BowVector& whole);
  void OnQuery(const bow_query_t& q, bool store);
  void OnMatch(const bow_match_t& m);
  void RecordAnswer(FrameId frame, RobotId responder, const std::optional<BowIndexMatch>& match);

  std::optional<BowIndexMatch> service_best_;  // its search's result, sent when the service ends
  BowTeamPlan plan_;
  const std::vector<BowVector>& vectors_;
  BowIndex index_;
  std::vector<std::vector<PartialMatch>> answers_;  // per own frame, while its replies come in
  std::vector<float> features_;                     // VerificationFeatures' buffer
};

}  // namespace dvpr
