#include "agents/bow_robot_agent.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "agents/messages/bow_query.h"
#include "agents/messages/channels.h"
#include "agents/messages/reply_message.h"

namespace dvpr {

BowRobotAgent::BowRobotAgent(const AgentSetup& setup, Transport& transport, BowTeamPlan plan,
                             const std::vector<BowVector>& vectors, GeometricVerifier verifier)
    : TaskServer(setup, setup.params.verification.bow_max_distance, transport, std::move(verifier)),
      plan_(std::move(plan)),
      vectors_(vectors) {
  if (plan_.robots != setup.robots) {
    throw std::invalid_argument("BowRobotAgent: a plan for " + std::to_string(plan_.robots) +
                                " robots in a team of " + std::to_string(setup.robots));
  }
  if (plan_.words != nullptr && plan_.words->robots() != plan_.robots) {
    throw std::invalid_argument("BowRobotAgent: the words are assigned to another team size");
  }
  const FrameStream& f = setup.frames;
  if (f.first.value < 0 || static_cast<std::size_t>(f.first.value + f.count) > vectors_.size()) {
    throw std::invalid_argument("BowRobotAgent: the robot's frames lie outside the BoW vectors");
  }
  answers_.resize(static_cast<std::size_t>(f.count));
}

std::vector<std::string> BowRobotAgent::InboxChannels(RobotId id) {
  std::vector<std::string> inbox{channels::BowQuery(id), channels::BowProbe(id), channels::BowMatch(id)};
  for (std::string& channel : VerificationChannels(id)) inbox.push_back(std::move(channel));
  return inbox;
}

void BowRobotAgent::Start() {
  Keep(transport_.Subscribe<bow_query_t>(channels::BowQuery(id_), [this](const bow_query_t& q) { OnQuery(q, true); }));
  Keep(transport_.Subscribe<bow_query_t>(channels::BowProbe(id_), [this](const bow_query_t& q) { OnQuery(q, false); }));
  Keep(transport_.Subscribe<bow_match_t>(channels::BowMatch(id_), [this](const bow_match_t& m) { OnMatch(m); }));
  SubscribeVerification();
  StartClock();
}

// The frame's part of each owner goes to that owner (broadcast: the whole vector to everyone);
// the robot's own part is searched and kept here like any other.
void BowRobotAgent::TakeFrame(int k) {
  const FrameId frame = FrameAt(k);
  const BowVector& whole = vectors_[static_cast<std::size_t>(frame.value)];
  std::vector<BowVector> parts;
  if (!plan_.broadcast()) parts = plan_.words->Split(whole);
  PublishParts(frame, parts, plan_.broadcast(), whole);
  int remote = 0;
  for (int r = 0; r < plan_.robots; ++r) {
    if (r != id_.value && (plan_.broadcast() || !parts[static_cast<std::size_t>(r)].empty())) ++remote;
  }
  const BowVector& own = plan_.broadcast() ? whole : parts[static_cast<std::size_t>(id_.value)];
  // A frame no robot is asked about is searched here all the same (empty: no match), so every
  // frame taken is a query with a complete record.
  const bool search_here = !own.empty() || remote == 0;
  BeginQuery(k, remote + (search_here ? 1 : 0));
  if (search_here) EnqueueSearch(id_, frame, true, [&](BowSearch& job) { job.part = own; });
}

void BowRobotAgent::PublishParts(FrameId frame, const std::vector<BowVector>& parts, bool broadcast,
                                 const BowVector& whole) {
  for (int r = 0; r < plan_.robots; ++r) {
    if (r == id_.value) continue;
    const BowVector& part = broadcast ? whole : parts[static_cast<std::size_t>(r)];
    if (!broadcast && part.empty()) continue;
    bow_query_t q = MakeBowQuery(id_, frame, part, SimTime::Zero());
    q.utime = transport_.Utime();
    transport_.Publish(broadcast ? channels::BowProbe(RobotId(r)) : channels::BowQuery(RobotId(r)), q);
  }
}

// The payload stands for the query's keypoints (verification_payload.h), here derived from its
// BoW weights.
std::span<const float> BowRobotAgent::VerificationFeatures(FrameId frame) {
  features_.clear();
  for (const BowEntry& e : vectors_[static_cast<std::size_t>(frame.value)]) features_.push_back(e.weight);
  return features_;
}

// The part is scored against what is stored when service starts; the reply goes out (and the
// part is stored) when the service time has elapsed.
std::int64_t BowRobotAgent::Search(Task& task) {
  const BowSearchResult result = index_.Search(task.job.part, task.frame, window_);
  service_best_ = result.best;
  return result.comparisons;
}

void BowRobotAgent::Searched(const Task& task) {
  const std::optional<BowIndexMatch>& best = service_best_;
  if (task.store && !task.job.part.empty()) index_.Add(task.querier, task.frame, task.job.part);
  if (task.querier == id_) {
    RecordAnswer(task.frame, id_, best);
    return;
  }
  bow_match_t m = MakeReply<bow_match_t>(transport_.Utime(), task.querier, task.frame, id_, best);
  m.score = best ? best->score : 0.0;
  transport_.Publish(channels::BowMatch(task.querier), m);
}

// Messages from a real network are checked before use: robots of the team (AgentCore), frames
// of the sequence.
void BowRobotAgent::OnQuery(const bow_query_t& q, bool store) {
  if (!online_ || q.robot == id_.value || Foreign(q.robot)) return;
  if (q.frame < 0 || static_cast<std::size_t>(q.frame) >= vectors_.size()) return;
  EnqueueSearch(RobotId(q.robot), FrameId(q.frame), store, [&](BowSearch& job) { job.part = BowPartOf(q); });
}

void BowRobotAgent::OnMatch(const bow_match_t& m) {
  if (!online_ || m.query_robot != id_.value || LocalIndexOf(FrameId(m.query_frame)) < 0) return;
  if (!ReplyFromTeam(m.responder, m.has_match, m.match_robot)) return;
  std::optional<BowIndexMatch> match;
  if (m.has_match) {
    if (m.match_frame < 0 || static_cast<std::size_t>(m.match_frame) >= vectors_.size()) return;
    match = BowIndexMatch{RobotId(m.match_robot), FrameId(m.match_frame), m.score};
  }
  RecordAnswer(FrameId(m.query_frame), RobotId(m.responder), match);
}

void BowRobotAgent::RecordAnswer(FrameId frame, RobotId responder, const std::optional<BowIndexMatch>& match) {
  const int k = AcceptReply(frame, responder);
  if (k < 0) return;
  if (match) answers_[static_cast<std::size_t>(k)].push_back({responder, match->robot, match->frame, match->score});
  Replied(k);
}

// The answers in responder order, so the sum of the scores does not depend on arrival order.
void BowRobotAgent::Conclude(int k) {
  std::vector<PartialMatch>& answers = answers_[static_cast<std::size_t>(k)];
  std::sort(answers.begin(), answers.end(),
            [](const PartialMatch& x, const PartialMatch& y) { return x.responder < y.responder; });
  if (const std::optional<VotedMatch> voted = Vote(answers)) {
    Record(k).best = IndexMatch{voted->match_robot, voted->frame, static_cast<float>(1.0 - voted->score)};
  }
  answers = {};
}

}  // namespace dvpr
