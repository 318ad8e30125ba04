#pragma once
// One robot of a bag-of-words team (docs/bow.md): the distributed inverted index of Cieslewski
// and Scaramuzza (ICRA 2017) as messages, built like RobotAgent (the same Transport, QueryRecord,
// RobotLoad, FIFO task queue, service-time model and verification exchange).
//
// Per frame it takes, the robot splits its L1-normalised BoW vector by word owner
// (BowTeamPlan::words), publishes one bow_query_t to each other owner of a non-empty part
// (channels::BowQuery), scores its own part locally, and waits for the replies. A responder
// scores the part against what it stored (BowIndex), replies with its best frame, the robot that
// observed it and the partial score (bow_match_t on channels::BowMatch), then stores the part.
// With every reply in, the querying robot votes (Vote, agents/bow_words.h; the answers in
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
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "agents/agent_params.h"
#include "agents/bow_index.h"
#include "agents/bow_vector.h"
#include "agents/bow_words.h"
#include "agents/frame_stream.h"
#include "agents/geometric_verifier.h"
#include "agents/team_agent.h"
#include "agents/transport.h"

namespace dvpr {

// How a BoW team splits and sends its queries: the same for every robot of the team.
struct BowTeamPlan {
  int robots = 0;
  // Who owns each word (scores and keeps its share of every query); null: bow_broadcast.
  std::shared_ptr<const WordOwners> words;
  bool broadcast() const { return words == nullptr; }
};

class BowRobotAgent final : public TeamAgent {
 public:
  // `frames` gives when the robot takes which frames (its descriptors are not used);
  // `vectors` holds every frame of the sequence (read when a frame is taken and for the
  // verification payload) and outlives the agent.
  BowRobotAgent(RobotId id, const AgentParams& params, Transport& transport, BowTeamPlan plan, FrameStream frames,
                const std::vector<BowVector>& vectors, GeometricVerifier verifier);
  BowRobotAgent(const BowRobotAgent&) = delete;
  BowRobotAgent& operator=(const BowRobotAgent&) = delete;

  void Start() override;
  static std::vector<std::string> InboxChannels(RobotId id);
  std::vector<std::string> Inbox() const override { return InboxChannels(id_); }
  void GoOffline() override;

  RobotId id() const override { return id_; }
  const std::vector<QueryRecord>& outcomes() const override { return outcomes_; }
  RobotLoad load() const override;
  const BowIndex& index() const { return index_; }

 private:
  struct Task {
    enum class Kind { kSearch, kVerify } kind = Kind::kSearch;
    RobotId querier;
    FrameId frame;
    BowVector part;       // kSearch
    bool store = false;   // kSearch: keep the part after scoring it
    FrameId match_frame;  // kVerify
  };
  struct Answers {        // per own frame, while its replies come in
    std::vector<std::int16_t> responders;
    std::vector<PartialMatch> matches;
  };

  void TakeFrame(int k);
  void PublishParts(FrameId frame, const std::vector<BowVector>& parts, bool broadcast, const BowVector& whole);
  void Enqueue(Task task);
  void StartNextTask();
  void ServeSearch(Task task);
  void ServeVerify(Task task);
  void OnQuery(const bow_query_t& q, bool store);
  void OnMatch(const bow_match_t& m);
  void OnVerifyRequest(const verify_request_t& r);
  void OnVerifyResult(const verify_result_t& r);
  void RecordAnswer(FrameId frame, RobotId responder, const std::optional<BowIndexMatch>& match);
  void MaybeVerify(int k);
  int LocalIndexOf(FrameId frame) const;

  RobotId id_;
  AgentParams params_;
  Transport& transport_;
  BowTeamPlan plan_;
  FrameStream frames_;
  const std::vector<BowVector>& vectors_;
  GeometricVerifier verifier_;
  BowIndex index_;
  std::vector<QueryRecord> outcomes_;
  std::vector<Answers> answers_;
  RobotLoad load_;
  std::deque<Task> queue_;
  bool busy_ = false;
  bool online_ = true;
  std::vector<Subscription> subscriptions_;
};

}  // namespace dvpr
