#include "agents/robot_agent.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "agents/channels.h"
#include "agents/recluster_agent.h"  // ReclusterState complete for the constructor

namespace dvpr {

SimTime FrameStream::TimeOf(int k) const {
  return SimTime::Nanos(std::llround(static_cast<double>(k) * 1e9 / fps));
}

RobotAgent::RobotAgent(RobotId id, const AgentParams& params, Transport& transport, const RoutingStrategy& routing,
                       FrameStream frames, GeometricVerifier verifier)
    : id_(id),
      params_(params),
      transport_(transport),
      routing_(routing),
      frames_(frames),
      verifier_(std::move(verifier)),
      index_(frames.descriptors != nullptr ? static_cast<int>(frames.descriptors->cols()) : 1) {
  params_.Validate();
  if (frames_.descriptors == nullptr) throw std::invalid_argument("RobotAgent: no descriptors");
  if (!(frames_.fps > 0.0)) throw std::invalid_argument("RobotAgent: fps must be positive");
  outcomes_.resize(static_cast<std::size_t>(frames_.count));
  InitRecluster();
}

void RobotAgent::Start() {
  subscriptions_.push_back(transport_.Subscribe<query_t>(channels::Query(id_), [this](const query_t& q) { OnQuery(q); }));
  subscriptions_.push_back(transport_.Subscribe<query_t>(channels::kQueryAll, [this](const query_t& q) { OnQuery(q); }));
  subscriptions_.push_back(transport_.Subscribe<match_t>(channels::Match(id_), [this](const match_t& m) { OnMatch(m); }));
  subscriptions_.push_back(transport_.Subscribe<verify_request_t>(
      channels::VerifyRequest(id_), [this](const verify_request_t& r) { OnVerifyRequest(r); }));
  subscriptions_.push_back(transport_.Subscribe<verify_result_t>(
      channels::VerifyResult(id_), [this](const verify_result_t& r) { OnVerifyResult(r); }));
  if (recluster_) StartRecluster();
  if (frames_.count > 0) {
    transport_.ScheduleAfter(frames_.TimeOf(0), [this] { TakeFrame(0); });
  }
}

// A robot that fails does not leave its channels: what others keep sending it
// is lost in the network (and counted there), not silently unaddressed.
void RobotAgent::GoOffline() {
  online_ = false;
  queue_.clear();
}

bool RobotAgent::Contains(const std::vector<RobotId>& robots, RobotId r) const {
  return std::find(robots.begin(), robots.end(), r) != robots.end();
}

int RobotAgent::LocalIndexOf(FrameId frame) const {
  const int k = frame.value - frames_.first.value;
  return (k >= 0 && k < frames_.count) ? k : -1;
}

void RobotAgent::TakeFrame(int k) {
  if (!online_) return;
  if (k + 1 < frames_.count) {
    transport_.ScheduleAfter(frames_.TimeOf(k + 1) - frames_.TimeOf(k), [this, k] { TakeFrame(k + 1); });
  }
  const FrameId frame(frames_.first.value + k);
  const float* descriptor = frames_.descriptors->row(frame.value).data();
  const RoutingDecision decision = recluster_ ? ReclusterRoute(descriptor) : routing_.Route(id_, descriptor);

  QueryOutcome& outcome = outcomes_[static_cast<std::size_t>(k)];
  outcome.frame = frame;
  outcome.sent = transport_.Now();
  outcome.expected_replies = static_cast<int>(decision.search_at.size());

  PublishQuery(k, decision);
  if (Contains(decision.search_at, id_)) {
    Task task;
    task.querier = id_;
    task.frame = frame;
    task.descriptor.assign(descriptor, descriptor + frames_.descriptors->cols());
    task.store = Contains(decision.store_at, id_);
    Enqueue(std::move(task));
  } else if (Contains(decision.store_at, id_)) {
    index_.Add(id_, frame, descriptor);
    ++load_.stored;
  }
}

void RobotAgent::PublishQuery(int k, const RoutingDecision& decision) {
  const FrameId frame(frames_.first.value + k);
  const auto dim = static_cast<int>(frames_.descriptors->cols());
  query_t q;
  q.utime = transport_.Now().us();
  q.robot = static_cast<std::int16_t>(id_.value);
  q.frame = frame.value;
  q.dim = static_cast<std::int16_t>(dim);
  const float* d = frames_.descriptors->row(frame.value).data();
  q.descriptor.assign(d, d + dim);

  // Robots that search it, then robots that only store it (boundary
  // replication); each remote robot gets the query once.
  std::vector<RobotId> remote;
  for (const auto* robots : {&decision.search_at, &decision.store_at}) {
    for (RobotId r : *robots) {
      if (r != id_ && !Contains(remote, r)) remote.push_back(r);
    }
  }
  if (remote.empty()) return;
  if (routing_.UsesBroadcastChannel()) {
    transport_.Publish(channels::kQueryAll, q);
    return;
  }
  for (RobotId r : remote) transport_.Publish(channels::Query(r), q);
}

void RobotAgent::Enqueue(Task task) {
  if (!online_) return;
  queue_.push_back(std::move(task));
  if (busy_) {
    load_.max_queue = std::max<std::int64_t>(load_.max_queue, static_cast<std::int64_t>(queue_.size()));
  }
  StartNextTask();
}

void RobotAgent::StartNextTask() {
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

// The search runs on what is stored when service starts; its result is
// delivered when the service time has elapsed.
void RobotAgent::ServeSearch(Task task) {
  IndexSearchResult result = index_.Search(task.descriptor.data(), task.frame, params_.suppression_frames);
  const SimTime duration = params_.service.fixed + params_.service.per_comparison * result.comparisons;
  ++load_.searches;
  if (task.querier != id_) ++load_.remote_queries;
  load_.comparisons += result.comparisons;
  load_.busy += duration;

  transport_.ScheduleAfter(duration, [this, task = std::move(task), best = result.best] {
    if (!online_) return;
    if (task.store) StoreQuery(task.querier, task.frame, task.descriptor.data());
    if (task.querier == id_) {
      RecordReply(task.frame, best);
    } else {
      match_t m;
      m.utime = transport_.Now().us();
      m.query_robot = static_cast<std::int16_t>(task.querier.value);
      m.query_frame = task.frame.value;
      m.responder = static_cast<std::int16_t>(id_.value);
      m.has_match = best.has_value();
      m.match_robot = best ? static_cast<std::int16_t>(best->robot.value) : std::int16_t{-1};
      m.match_frame = best ? best->frame.value : -1;
      m.distance = best ? best->distance : 0.0f;
      transport_.Publish(channels::Match(task.querier), m);
    }
    busy_ = false;
    StartNextTask();
  });
}

void RobotAgent::ServeVerify(Task task) {
  ++load_.verifications;
  load_.busy += params_.service.fixed;
  transport_.ScheduleAfter(params_.service.fixed, [this, task = std::move(task)] {
    if (!online_) return;
    const VerifyVerdict verdict = verifier_(task.frame, task.match_frame);
    if (task.querier == id_) {
      QueryOutcome& o = outcomes_[static_cast<std::size_t>(LocalIndexOf(task.frame))];
      o.verify_accepted = verdict.accepted;
      o.verify_done = transport_.Now();
    } else {
      verify_result_t v;
      v.utime = transport_.Now().us();
      v.query_robot = static_cast<std::int16_t>(task.querier.value);
      v.query_frame = task.frame.value;
      v.match_robot = static_cast<std::int16_t>(id_.value);
      v.match_frame = task.match_frame.value;
      v.accepted = verdict.accepted;
      v.inliers = verdict.inliers;
      transport_.Publish(channels::VerifyResult(task.querier), v);
    }
    busy_ = false;
    StartNextTask();
  });
}

// The routing decision is re-evaluated here (strategies are deterministic):
// a robot asked to search serves the query; a robot that is only a replica
// stores it and sends nothing back.
void RobotAgent::OnQuery(const query_t& q) {
  if (!online_ || q.robot == id_.value || q.dim != frames_.descriptors->cols()) return;
  // Re-clustering: the receiver always searches; StoreQuery keeps or forwards by its own table.
  const RoutingStrategy::Role role =
      recluster_ ? RoutingStrategy::Role{true, true} : routing_.RoleOf(RobotId(q.robot), q.descriptor.data(), id_);
  if (!role.search) {
    if (role.store) {
      index_.Add(RobotId(q.robot), FrameId(q.frame), q.descriptor.data());
      ++load_.stored;
    }
    return;
  }
  Task task;
  task.querier = RobotId(q.robot);
  task.frame = FrameId(q.frame);
  task.descriptor = q.descriptor;
  task.store = role.store;
  Enqueue(std::move(task));
}

void RobotAgent::StoreQuery(RobotId robot, FrameId frame, const float* descriptor) {
  if (recluster_) {
    StoreOrForward(robot, frame, descriptor);
    return;
  }
  index_.Add(robot, frame, descriptor);
  ++load_.stored;
}

void RobotAgent::OnMatch(const match_t& m) {
  if (!online_) return;
  if (m.query_robot != id_.value || LocalIndexOf(FrameId(m.query_frame)) < 0) return;
  std::optional<IndexMatch> match;
  if (m.has_match) match = IndexMatch{RobotId(m.match_robot), FrameId(m.match_frame), m.distance};
  RecordReply(FrameId(m.query_frame), match);
}

void RobotAgent::RecordReply(FrameId frame, const std::optional<IndexMatch>& match) {
  const int k = LocalIndexOf(frame);
  QueryOutcome& o = outcomes_[static_cast<std::size_t>(k)];
  if (o.received_replies >= o.expected_replies) return;  // a duplicate (real networks)
  ++o.received_replies;
  o.last_reply = transport_.Now();
  // Ties keep the earlier reply, so the outcome does not depend on arrival order
  // only through equal distances.
  if (match && (!o.best || match->distance < o.best->distance)) o.best = match;
  if (o.Complete()) MaybeVerify(k);
}

void RobotAgent::MaybeVerify(int k) {
  QueryOutcome& o = outcomes_[static_cast<std::size_t>(k)];
  if (!o.best || o.best->distance > static_cast<float>(params_.verification.max_distance)) return;
  o.verify_requested = true;
  if (o.best->robot == id_) {
    Task task;
    task.kind = Task::Kind::kVerify;
    task.querier = id_;
    task.frame = o.frame;
    task.match_robot = id_;
    task.match_frame = o.best->frame;
    Enqueue(std::move(task));
    return;
  }
  verify_request_t r;
  r.utime = transport_.Now().us();
  r.query_robot = static_cast<std::int16_t>(id_.value);
  r.query_frame = o.frame.value;
  r.match_robot = static_cast<std::int16_t>(o.best->robot.value);
  r.match_frame = o.best->frame.value;
  r.payload_size = static_cast<std::int32_t>(params_.verification.request_bytes.value());
  r.payload.assign(static_cast<std::size_t>(r.payload_size), 0);
  transport_.Publish(channels::VerifyRequest(o.best->robot), r);
}

void RobotAgent::OnVerifyRequest(const verify_request_t& r) {
  if (!online_) return;
  if (r.match_robot != id_.value) return;
  Task task;
  task.kind = Task::Kind::kVerify;
  task.querier = RobotId(r.query_robot);
  task.frame = FrameId(r.query_frame);
  task.match_robot = id_;
  task.match_frame = FrameId(r.match_frame);
  Enqueue(std::move(task));
}

void RobotAgent::OnVerifyResult(const verify_result_t& r) {
  if (!online_) return;
  const int k = LocalIndexOf(FrameId(r.query_frame));
  if (r.query_robot != id_.value || k < 0) return;
  QueryOutcome& o = outcomes_[static_cast<std::size_t>(k)];
  o.verify_accepted = r.accepted;
  o.verify_done = transport_.Now();
}

}  // namespace dvpr
