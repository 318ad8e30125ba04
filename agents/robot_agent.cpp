#include "agents/robot_agent.h"

#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "agents/verification_payload.h"
#include "agents/verify_messages.h"

namespace dvpr {

RobotAgent::RobotAgent(RobotId id, const AgentParams& params, Transport& transport, std::unique_ptr<AgentRouting> routing,
                       FrameStream frames, GeometricVerifier verifier)
    : id_(id),
      params_(params),
      transport_(transport),
      frames_(frames),
      verifier_(std::move(verifier)),
      index_(frames.descriptors != nullptr ? static_cast<int>(frames.descriptors->cols()) : 1),
      routing_(std::move(routing)) {
  params_.Validate();
  if (frames_.descriptors == nullptr) throw std::invalid_argument("RobotAgent: no descriptors");
  if (!(frames_.fps > 0.0)) throw std::invalid_argument("RobotAgent: fps must be positive");
  if (routing_ == nullptr) throw std::invalid_argument("RobotAgent: no routing");
  outcomes_.resize(static_cast<std::size_t>(frames_.count));
}

RobotLoad RobotAgent::load() const {
  RobotLoad load = load_;
  load.stored = static_cast<std::int64_t>(index_.size());
  return load;
}

std::vector<std::string> RobotAgent::InboxChannels(RobotId id) {
  return {channels::Query(id),         channels::Probe(id),         channels::Store(id),
          std::string(channels::kQueryAll), channels::Match(id), channels::VerifyRequest(id),
          channels::VerifyResult(id)};
}

void RobotAgent::Start() {
  const auto on_query = [this](QueryRole role) {
    return [this, role](const MessageRef<query_t>& q) { OnQuery(q, role); };
  };
  const auto subscribe_query = [&](const std::string& channel, QueryRole role) {
    subscriptions_.push_back(transport_.SubscribeShared<query_t>(channel, on_query(role)));
  };
  subscribe_query(channels::Query(id_), QueryRole::kSearchAndStore);
  subscribe_query(channels::Probe(id_), QueryRole::kSearch);
  subscribe_query(channels::Store(id_), QueryRole::kStore);
  subscribe_query(std::string(channels::kQueryAll), QueryRole::kSearch);
  subscriptions_.push_back(transport_.Subscribe<match_t>(channels::Match(id_), [this](const match_t& m) { OnMatch(m); }));
  subscriptions_.push_back(transport_.Subscribe<verify_request_t>(
      channels::VerifyRequest(id_), [this](const verify_request_t& r) { OnVerifyRequest(r); }));
  subscriptions_.push_back(transport_.Subscribe<verify_result_t>(
      channels::VerifyResult(id_), [this](const verify_result_t& r) { OnVerifyResult(r); }));
  routing_->Start(AgentContext{id_, transport_, index_, frames_});
  if (frames_.count > 0) {
    transport_.ScheduleAfter(frames_.TimeOf(0), [this] { TakeFrame(0); });
  }
}

// A robot that fails does not leave its channels: what others keep sending it
// is lost in the network (and counted there), not silently unaddressed.
void RobotAgent::GoOffline() {
  online_ = false;
  queue_.clear();
  routing_->Stop();
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
  const QueryPlan plan = routing_->Plan(descriptor);

  QueryRecord& outcome = outcomes_[static_cast<std::size_t>(k)];
  outcome.robot = id_;
  outcome.frame = frame;
  outcome.sent = transport_.Now();
  outcome.expected_replies = plan.searches;

  PublishQuery(k, plan);
  if (plan.search_here) {
    EnqueueSearch(id_, frame, descriptor, plan.store_here);
  } else if (plan.store_here) {
    routing_->Store(id_, frame, descriptor);
  }
}

void RobotAgent::PublishQuery(int k, const QueryPlan& plan) {
  if (plan.channels.empty()) return;
  const FrameId frame(frames_.first.value + k);
  const auto dim = static_cast<int>(frames_.descriptors->cols());
  query_t q;
  q.utime = transport_.Utime();
  q.robot = static_cast<std::int16_t>(id_.value);
  q.frame = frame.value;
  q.capture_utime = transport_.UtimeAt(frames_.TimeOf(k));
  q.dim = static_cast<std::int16_t>(dim);
  const float* d = frames_.descriptors->row(frame.value).data();
  q.descriptor.assign(d, d + dim);
  for (const std::string& channel : plan.channels) transport_.Publish(channel, q);
}

void RobotAgent::EnqueueSearch(RobotId querier, FrameId frame, const float* descriptor, bool store,
                               MessageRef<query_t> message) {
  if (!online_) return;
  Task& task = PushTask(Task::Kind::kSearch, querier, frame);
  task.store = store;
  task.descriptor = descriptor;
  task.message = std::move(message);
  Enqueued();
}

void RobotAgent::EnqueueVerify(RobotId querier, FrameId frame, FrameId match_frame) {
  if (!online_) return;
  Task& task = PushTask(Task::Kind::kVerify, querier, frame);
  task.store = false;
  task.match_robot = id_;
  task.match_frame = match_frame;
  Enqueued();
}

// The back slot with every field reset (the message it held, if any, let go); an idle robot's
// task goes straight into service (its queue is empty: StartNextTask empties it before it idles),
// not through a queue slot and a swap.
RobotAgent::Task& RobotAgent::PushTask(Task::Kind kind, RobotId querier, FrameId frame) {
  Task& task = busy_ ? queue_.Push() : in_service_;
  task.kind = kind;
  task.querier = querier;
  task.frame = frame;
  task.store = false;
  task.match_frame = FrameId();
  task.match_robot = RobotId();
  task.descriptor = nullptr;
  task.message.Reset();
  task.searched_at = 0;
  return task;
}

void RobotAgent::Enqueued() {
  if (busy_) {
    load_.max_queue = std::max<std::int64_t>(load_.max_queue, static_cast<std::int64_t>(queue_.size()));
    return;
  }
  busy_ = true;  // PushTask put the task in service
  Serve();
}

void RobotAgent::StartNextTask() {
  if (busy_ || queue_.empty() || !online_) return;
  busy_ = true;
  queue_.PopInto(in_service_);
  Serve();
}

void RobotAgent::Serve() {
  if (in_service_.kind == Task::Kind::kSearch) {
    ServeSearch();
  } else {
    ServeVerify();
  }
}

// The search runs on what is stored when service starts; its result is
// delivered when the service time has elapsed.
void RobotAgent::ServeSearch() {
  const Task& task = in_service_;
  if (task.searched_at != index_.changes() + 1) SearchAhead();
  const IndexSearchResult& result = task.result;
  const SimTime duration = params_.service.fixed + params_.service.per_comparison * result.comparisons;
  ++load_.searches;
  if (task.querier != id_) ++load_.remote_queries;
  load_.comparisons += result.comparisons;
  load_.busy += duration;
  service_best_ = result.best;
  transport_.ScheduleAfter(duration, [this] { FinishSearch(); });
}

// The results are those the searches would give when served: the store is the same until then
// (changes() says whether it is). A search's result depends on nothing else (the index's hint
// only saves work).
void RobotAgent::SearchAhead() {
  const std::uint64_t version = index_.changes() + 1;
  bool ahead = true;  // no search before it stores
  const auto search = [&](Task& t) {
    if (!ahead || t.kind != Task::Kind::kSearch) return;
    if (t.searched_at != version) {
      t.result = index_.Search(t.descriptor, t.frame, params_.suppression_frames);
      t.searched_at = version;
    }
    ahead = !t.store;
  };
  search(in_service_);
  queue_.ForEach(search);
}

void RobotAgent::FinishSearch() {
  if (!online_) return;
  const Task& task = in_service_;
  const std::optional<IndexMatch>& best = service_best_;
  if (task.store) routing_->Store(task.querier, task.frame, task.descriptor);
  if (task.querier == id_) {
    RecordReply(task.frame, best);
  } else {
    match_t m;
    m.utime = transport_.Utime();
    m.query_robot = static_cast<std::int16_t>(task.querier.value);
    m.query_frame = task.frame.value;
    m.responder = static_cast<std::int16_t>(id_.value);
    m.has_match = best.has_value();
    m.match_robot = best ? static_cast<std::int16_t>(best->robot.value) : std::int16_t{-1};
    m.match_frame = best ? best->frame.value : -1;
    m.distance = best ? best->distance : 0.0f;
    transport_.Publish(ChannelOf(match_channels_, task.querier, channels::Match), m);
  }
  EndService();
}

void RobotAgent::ServeVerify() {
  ++load_.verifications;
  load_.busy += params_.service.fixed;
  transport_.ScheduleAfter(params_.service.fixed, [this] { FinishVerify(); });
}

void RobotAgent::FinishVerify() {
  if (!online_) return;
  const Task& task = in_service_;
  const VerifyVerdict verdict = verifier_(task.frame, task.match_frame);
  if (task.querier == id_) {
    outcomes_[static_cast<std::size_t>(LocalIndexOf(task.frame))].verify_accepted = verdict.accepted;
  } else {
    transport_.Publish(ChannelOf(verify_result_channels_, task.querier, channels::VerifyResult),
                       MakeVerifyResult(transport_.Utime(), task.querier, task.frame, id_, task.match_frame, verdict));
  }
  EndService();
}

// The finished task lets go of its query (the decoded message goes back to the pool once the
// other robots that queued it are done with it too).
void RobotAgent::EndService() {
  in_service_.message.Reset();
  in_service_.descriptor = nullptr;
  busy_ = false;
  StartNextTask();
}

// Interned once per robot instead of named and looked up once per message. Ids come from int16
// fields of the wire, so a table stays below 32768 entries; a negative one (garbage) is
// interned by name each time (the transport keeps one entry a name).
PublishChannel RobotAgent::ChannelOf(std::vector<std::uint32_t>& by_robot, RobotId robot,
                                     std::string (*name)(RobotId)) {
  if (robot.value < 0) return transport_.Intern(name(robot));
  const auto i = static_cast<std::size_t>(robot.value);
  if (i >= by_robot.size()) by_robot.resize(i + 1, kNoChannel);
  if (by_robot[i] == kNoChannel) by_robot[i] = static_cast<std::uint32_t>(transport_.Intern(name(robot)));
  return PublishChannel{by_robot[i]};
}

// The channel the query came on says what to do with it: a robot asked to
// search serves the query (and stores it afterwards when asked to); a robot
// that is only a replica stores it and sends nothing back.
void RobotAgent::OnQuery(const MessageRef<query_t>& message, QueryRole role) {
  const query_t& q = *message;
  if (!online_ || q.robot == id_.value || q.dim != frames_.descriptors->cols()) return;
  if (role == QueryRole::kStore) {
    routing_->Store(RobotId(q.robot), FrameId(q.frame), q.descriptor.data());
    return;
  }
  EnqueueSearch(RobotId(q.robot), FrameId(q.frame), q.descriptor.data(), role == QueryRole::kSearchAndStore, message);
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
  QueryRecord& o = outcomes_[static_cast<std::size_t>(k)];
  if (o.received_replies >= o.expected_replies) return;  // a duplicate (real networks)
  ++o.received_replies;
  // Ties keep the earlier reply, so the outcome does not depend on arrival order
  // only through equal distances.
  if (match && (!o.best || match->distance < o.best->distance)) o.best = match;
  if (!o.Complete()) return;
  o.latency = transport_.Now() - o.sent;
  MaybeVerify(k);
}

void RobotAgent::MaybeVerify(int k) {
  QueryRecord& o = outcomes_[static_cast<std::size_t>(k)];
  if (!o.best || o.best->distance > static_cast<float>(params_.verification.max_distance)) return;
  o.verify_requested = true;
  if (o.best->robot == id_) {
    EnqueueVerify(id_, o.frame, o.best->frame);
    return;
  }
  verify_request_t& r = verify_request_;  // reused: its payload buffer is refilled, not reallocated
  FillVerifyRequest(r, transport_.Utime(), id_, o.frame, o.best->robot, o.best->frame,
                    static_cast<std::int32_t>(params_.verification.request_bytes.value()));
  const auto dim = static_cast<std::size_t>(frames_.descriptors->cols());
  FillVerificationPayload(o.frame, std::span<const float>(frames_.descriptors->row(o.frame.value).data(), dim),
                          r.payload);
  transport_.Publish(ChannelOf(verify_request_channels_, o.best->robot, channels::VerifyRequest), r);
}

void RobotAgent::OnVerifyRequest(const verify_request_t& r) {
  if (!online_) return;
  if (r.match_robot != id_.value) return;
  EnqueueVerify(RobotId(r.query_robot), FrameId(r.query_frame), FrameId(r.match_frame));
}

void RobotAgent::OnVerifyResult(const verify_result_t& r) {
  if (!online_) return;
  const int k = LocalIndexOf(FrameId(r.query_frame));
  if (r.query_robot != id_.value || k < 0) return;
  outcomes_[static_cast<std::size_t>(k)].verify_accepted = r.accepted;
}

}  // namespace dvpr
