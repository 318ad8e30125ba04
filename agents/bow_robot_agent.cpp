#include "agents/bow_robot_agent.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "agents/bow_query.h"
#include "agents/channels.h"
#include "agents/verification_payload.h"
#include "agents/verify_messages.h"

namespace dvpr {

BowRobotAgent::BowRobotAgent(RobotId id, const AgentParams& params, Transport& transport, BowTeamPlan plan,
                             FrameStream frames, const std::vector<BowVector>& vectors, GeometricVerifier verifier)
    : id_(id),
      params_(params),
      transport_(transport),
      plan_(std::move(plan)),
      frames_(frames),
      vectors_(vectors),
      verifier_(std::move(verifier)) {
  params_.Validate();
  if (plan_.robots < 1 || id_.value < 0 || id_.value >= plan_.robots) {
    throw std::invalid_argument("BowRobotAgent: robot " + std::to_string(id_.value) + " is not in a team of " +
                                std::to_string(plan_.robots));
  }
  if (plan_.words != nullptr && plan_.words->robots() != plan_.robots) {
    throw std::invalid_argument("BowRobotAgent: the words are assigned to another team size");
  }
  if (!(frames_.fps > 0.0)) throw std::invalid_argument("BowRobotAgent: fps must be positive");
  if (frames_.first.value < 0 || static_cast<std::size_t>(frames_.first.value + frames_.count) > vectors_.size()) {
    throw std::invalid_argument("BowRobotAgent: the robot's frames lie outside the BoW vectors");
  }
  outcomes_.resize(static_cast<std::size_t>(frames_.count));
  answers_.resize(static_cast<std::size_t>(frames_.count));
}

RobotLoad BowRobotAgent::load() const {
  RobotLoad load = load_;
  load.stored = index_.parts();
  return load;
}

std::vector<std::string> BowRobotAgent::InboxChannels(RobotId id) {
  return {channels::BowQuery(id), channels::BowProbe(id), channels::BowMatch(id), channels::VerifyRequest(id),
          channels::VerifyResult(id)};
}

void BowRobotAgent::Start() {
  subscriptions_.push_back(
      transport_.Subscribe<bow_query_t>(channels::BowQuery(id_), [this](const bow_query_t& q) { OnQuery(q, true); }));
  subscriptions_.push_back(
      transport_.Subscribe<bow_query_t>(channels::BowProbe(id_), [this](const bow_query_t& q) { OnQuery(q, false); }));
  subscriptions_.push_back(
      transport_.Subscribe<bow_match_t>(channels::BowMatch(id_), [this](const bow_match_t& m) { OnMatch(m); }));
  subscriptions_.push_back(transport_.Subscribe<verify_request_t>(
      channels::VerifyRequest(id_), [this](const verify_request_t& r) { OnVerifyRequest(r); }));
  subscriptions_.push_back(transport_.Subscribe<verify_result_t>(
      channels::VerifyResult(id_), [this](const verify_result_t& r) { OnVerifyResult(r); }));
  if (frames_.count > 0) {
    transport_.ScheduleAfter(frames_.TimeOf(0), [this] { TakeFrame(0); });
  }
}

// As RobotAgent: a robot that fails keeps its channels; what is sent to it is lost in the network.
void BowRobotAgent::GoOffline() {
  online_ = false;
  queue_.clear();
}

int BowRobotAgent::LocalIndexOf(FrameId frame) const {
  const int k = frame.value - frames_.first.value;
  return (k >= 0 && k < frames_.count) ? k : -1;
}

void BowRobotAgent::TakeFrame(int k) {
  if (!online_) return;
  if (k + 1 < frames_.count) {
    transport_.ScheduleAfter(frames_.TimeOf(k + 1) - frames_.TimeOf(k), [this, k] { TakeFrame(k + 1); });
  }
  const FrameId frame(frames_.first.value + k);
  const BowVector& whole = vectors_[static_cast<std::size_t>(frame.value)];
  QueryRecord& outcome = outcomes_[static_cast<std::size_t>(k)];
  outcome.robot = id_;
  outcome.frame = frame;
  outcome.sent = transport_.Now();

  Task local;
  local.querier = id_;
  local.frame = frame;
  local.store = true;  // the own part (broadcast: the own frame) is kept like any other
  std::vector<BowVector> parts;
  if (!plan_.broadcast()) parts = plan_.words->Split(whole);
  PublishParts(frame, parts, plan_.broadcast(), whole);
  int remote = 0;
  for (int r = 0; r < plan_.robots; ++r) {
    if (r != id_.value && (plan_.broadcast() || !parts[static_cast<std::size_t>(r)].empty())) ++remote;
  }
  local.part = plan_.broadcast() ? whole : parts[static_cast<std::size_t>(id_.value)];
  // A frame no robot is asked about is searched here all the same (empty: no match), so every
  // frame taken is a query with a complete record.
  const bool search_here = !local.part.empty() || remote == 0;
  outcome.expected_replies = remote + (search_here ? 1 : 0);
  if (search_here) Enqueue(std::move(local));
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

void BowRobotAgent::Enqueue(Task task) {
  if (!online_) return;
  queue_.push_back(std::move(task));
  if (busy_) {
    load_.max_queue = std::max<std::int64_t>(load_.max_queue, static_cast<std::int64_t>(queue_.size()));
  }
  StartNextTask();
}

void BowRobotAgent::StartNextTask() {
  if (busy_ || queue_.empty() || !online_) return;
  busy_ = true;
  Task task = std::move(queue_.front());
  queue_.pop_front();
  if (task.kind == Task::Kind::kSearch) {
    ServeSearch(std::move(task));
  } else {
    ServeVerify(std::move(task));
  }
}

// As RobotAgent: the part is scored against what is stored when service starts, the reply goes
// out (and the part is stored) when the service time has elapsed.
void BowRobotAgent::ServeSearch(Task task) {
  const BowSearchResult result = index_.Search(task.part, task.frame, params_.suppression_frames);
  const SimTime duration = params_.service.fixed + params_.service.per_comparison * result.comparisons;
  ++load_.searches;
  if (task.querier != id_) ++load_.remote_queries;
  load_.comparisons += result.comparisons;
  load_.busy += duration;

  transport_.ScheduleAfter(duration, [this, task = std::move(task), best = result.best] {
    if (!online_) return;
    if (task.store && !task.part.empty()) index_.Add(task.querier, task.frame, task.part);
    if (task.querier == id_) {
      RecordAnswer(task.frame, id_, best);
    } else {
      bow_match_t m;
      m.utime = transport_.Utime();
      m.query_robot = static_cast<std::int16_t>(task.querier.value);
      m.query_frame = task.frame.value;
      m.responder = static_cast<std::int16_t>(id_.value);
      m.has_match = best.has_value();
      m.match_robot = best ? static_cast<std::int16_t>(best->robot.value) : std::int16_t{-1};
      m.match_frame = best ? best->frame.value : -1;
      m.score = best ? best->score : 0.0;
      transport_.Publish(channels::BowMatch(task.querier), m);
    }
    busy_ = false;
    StartNextTask();
  });
}

void BowRobotAgent::ServeVerify(Task task) {
  ++load_.verifications;
  load_.busy += params_.service.fixed;
  transport_.ScheduleAfter(params_.service.fixed, [this, task = std::move(task)] {
    if (!online_) return;
    const VerifyVerdict verdict = verifier_(task.frame, task.match_frame);
    if (task.querier == id_) {
      outcomes_[static_cast<std::size_t>(LocalIndexOf(task.frame))].verify_accepted = verdict.accepted;
    } else {
      transport_.Publish(channels::VerifyResult(task.querier),
                         MakeVerifyResult(transport_.Utime(), task.querier, task.frame, id_, task.match_frame, verdict));
    }
    busy_ = false;
    StartNextTask();
  });
}

// Messages from a real network are checked before use: robots of the team, frames of the sequence.
void BowRobotAgent::OnQuery(const bow_query_t& q, bool store) {
  if (!online_ || q.robot == id_.value || q.robot < 0 || q.robot >= plan_.robots) return;
  if (q.frame < 0 || static_cast<std::size_t>(q.frame) >= vectors_.size()) return;
  Task task;
  task.querier = RobotId(q.robot);
  task.frame = FrameId(q.frame);
  task.part = BowPartOf(q);
  task.store = store;
  Enqueue(std::move(task));
}

void BowRobotAgent::OnMatch(const bow_match_t& m) {
  if (!online_ || m.query_robot != id_.value || LocalIndexOf(FrameId(m.query_frame)) < 0) return;
  if (m.responder < 0 || m.responder >= plan_.robots) return;
  std::optional<BowIndexMatch> match;
  if (m.has_match) {
    if (m.match_robot < 0 || m.match_robot >= plan_.robots || m.match_frame < 0 ||
        static_cast<std::size_t>(m.match_frame) >= vectors_.size()) {
      return;
    }
    match = BowIndexMatch{RobotId(m.match_robot), FrameId(m.match_frame), m.score};
  }
  RecordAnswer(FrameId(m.query_frame), RobotId(m.responder), match);
}

void BowRobotAgent::RecordAnswer(FrameId frame, RobotId responder, const std::optional<BowIndexMatch>& match) {
  const auto k = static_cast<std::size_t>(LocalIndexOf(frame));
  QueryRecord& o = outcomes_[k];
  Answers& a = answers_[k];
  if (o.received_replies >= o.expected_replies) return;  // a late duplicate (real networks)
  const auto r = static_cast<std::int16_t>(responder.value);
  if (std::find(a.responders.begin(), a.responders.end(), r) != a.responders.end()) return;  // a duplicate
  a.responders.push_back(r);
  ++o.received_replies;
  if (match) a.matches.push_back({responder, match->robot, match->frame, match->score});
  if (!o.Complete()) return;
  o.latency = transport_.Now() - o.sent;
  std::sort(a.matches.begin(), a.matches.end(),
            [](const PartialMatch& x, const PartialMatch& y) { return x.responder < y.responder; });
  if (const std::optional<VotedMatch> voted = Vote(a.matches)) {
    o.best = IndexMatch{voted->match_robot, voted->frame, static_cast<float>(1.0 - voted->score)};
  }
  a = Answers{};
  MaybeVerify(static_cast<int>(k));
}

void BowRobotAgent::MaybeVerify(int k) {
  QueryRecord& o = outcomes_[static_cast<std::size_t>(k)];
  if (!o.best || o.best->distance > static_cast<float>(params_.verification.bow_max_distance)) return;
  o.verify_requested = true;
  if (o.best->robot == id_) {
    Task task;
    task.kind = Task::Kind::kVerify;
    task.querier = id_;
    task.frame = o.frame;
    task.match_frame = o.best->frame;
    Enqueue(std::move(task));
    return;
  }
  verify_request_t r;
  FillVerifyRequest(r, transport_.Utime(), id_, o.frame, o.best->robot, o.best->frame,
                    static_cast<std::int32_t>(params_.verification.request_bytes.value()));
  // The payload stands for the query's keypoints (verification_payload.h), here derived from its
  // BoW weights.
  std::vector<float> weights;
  for (const BowEntry& e : vectors_[static_cast<std::size_t>(o.frame.value)]) weights.push_back(e.weight);
  FillVerificationPayload(o.frame, weights, r.payload);
  transport_.Publish(channels::VerifyRequest(o.best->robot), r);
}

void BowRobotAgent::OnVerifyRequest(const verify_request_t& r) {
  if (!online_ || r.match_robot != id_.value) return;
  if (r.query_robot < 0 || r.query_robot >= plan_.robots) return;
  Task task;
  task.kind = Task::Kind::kVerify;
  task.querier = RobotId(r.query_robot);
  task.frame = FrameId(r.query_frame);
  task.match_frame = FrameId(r.match_frame);
  Enqueue(std::move(task));
}

void BowRobotAgent::OnVerifyResult(const verify_result_t& r) {
  if (!online_) return;
  const int k = LocalIndexOf(FrameId(r.query_frame));
  if (r.query_robot != id_.value || k < 0) return;
  outcomes_[static_cast<std::size_t>(k)].verify_accepted = r.accepted;
}

}  // namespace dvpr
