#include "agents/robot_agent.h"

#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include "agents/messages/reply_message.h"

namespace dvpr {

namespace {

const DescriptorMatrix& DescriptorsOf(const AgentSetup& setup) {
  if (setup.frames.descriptors == nullptr) throw std::invalid_argument("RobotAgent: no descriptors");
  return *setup.frames.descriptors;
}

}  // namespace

RobotAgent::RobotAgent(const AgentSetup& setup, Transport& transport, std::unique_ptr<AgentPlacement> placement,
                       GeometricVerifier verifier)
    : TaskServer(setup, setup.params.verification.max_distance, transport, std::move(verifier)),
      descriptors_(&DescriptorsOf(setup)),
      index_(static_cast<int>(descriptors_->cols())),
      placement_(std::move(placement)) {
  if (placement_ == nullptr) throw std::invalid_argument("RobotAgent: no placement");
}

std::vector<std::string> RobotAgent::InboxChannels(RobotId id) {
  std::vector<std::string> inbox{channels::Query(id), channels::Probe(id), channels::Store(id),
                                 std::string(channels::kQueryAll), channels::Match(id)};
  for (std::string& channel : VerificationChannels(id)) inbox.push_back(std::move(channel));
  return inbox;
}

void RobotAgent::Start() {
  const auto subscribe_query = [&](const std::string& channel, QueryRole role) {
    Keep(transport_.SubscribeShared<query_t>(channel,
                                             [this, role](const MessageRef<query_t>& q) { OnQuery(q, role); }));
  };
  subscribe_query(channels::Query(id_), QueryRole::kSearchAndStore);
  subscribe_query(channels::Probe(id_), QueryRole::kSearch);
  subscribe_query(channels::Store(id_), QueryRole::kStore);
  subscribe_query(std::string(channels::kQueryAll), QueryRole::kSearch);
  Keep(transport_.Subscribe<match_t>(channels::Match(id_), [this](const match_t& m) { OnMatch(m); }));
  SubscribeVerification();
  placement_->Start(AgentContext{id_, transport_, index_, frames()});
  StartClock();
}

void RobotAgent::TakeFrame(int k) {
  const FrameId frame = FrameAt(k);
  const float* descriptor = DescriptorOf(frame);
  const QueryPlan plan = placement_->Plan(descriptor);
  BeginQuery(k, plan.searches);
  PublishQuery(k, plan);
  if (plan.search_here) {
    EnqueueSearch(id_, frame, plan.store_here, [&](DescriptorSearch& job) { job.descriptor = descriptor; });
  } else if (plan.store_here) {
    placement_->Store(id_, frame, descriptor);
  }
}

void RobotAgent::PublishQuery(int k, const QueryPlan& plan) {
  if (plan.channels.empty()) return;
  const FrameId frame = FrameAt(k);
  const auto dim = static_cast<int>(descriptors_->cols());
  query_t q;
  q.utime = transport_.Utime();
  q.robot = static_cast<std::int16_t>(id_.value);
  q.frame = frame.value;
  q.capture_utime = transport_.UtimeAt(frames().TimeOf(k));
  q.dim = static_cast<std::int16_t>(dim);
  const float* d = DescriptorOf(frame);
  q.descriptor.assign(d, d + dim);
  for (const std::string& channel : plan.channels) transport_.Publish(channel, q);
}

std::span<const float> RobotAgent::VerificationFeatures(FrameId frame) {
  return {DescriptorOf(frame), static_cast<std::size_t>(descriptors_->cols())};
}

// The search runs on what is stored when service starts; its result is delivered when the
// service time has elapsed.
std::int64_t RobotAgent::Search(Task& task) {
  if (task.job.searched_at != index_.changes() + 1) SearchAhead();
  service_best_ = task.job.result.best;
  return task.job.result.comparisons;
}

// The results are those the searches would give when served: the store is the same until then
// (changes() says whether it is). A search's result depends on nothing else (the index's hint
// only saves work).
void RobotAgent::SearchAhead() {
  const std::uint64_t version = index_.changes() + 1;
  bool ahead = true;  // no search before it stores
  const auto search = [&](Task& t) {
    if (!ahead || t.kind != Task::Kind::kSearch) return;
    if (t.job.searched_at != version) {
      t.job.result = index_.Search(t.job.descriptor, t.frame, window_);
      t.job.searched_at = version;
    }
    ahead = !t.store;
  };
  search(in_service_);
  queue_.ForEach(search);
}

void RobotAgent::Searched(const Task& task) {
  const std::optional<IndexMatch>& best = service_best_;
  if (task.store) placement_->Store(task.querier, task.frame, task.job.descriptor);
  if (task.querier == id_) {
    RecordReply(task.frame, id_, best);
    return;
  }
  match_t m = MakeReply<match_t>(transport_.Utime(), task.querier, task.frame, id_, best);
  m.distance = best ? best->distance : 0.0f;
  transport_.Publish(ChannelOf(match_channels_, task.querier, channels::Match), m);
}

// The channel the query came on says what to do with it: a robot asked to
// search serves the query (and stores it afterwards when asked to); a robot
// that is only a replica stores it and sends nothing back.
void RobotAgent::OnQuery(const MessageRef<query_t>& message, QueryRole role) {
  const query_t& q = *message;
  if (!online_ || q.robot == id_.value || Foreign(q.robot) || q.dim != descriptors_->cols()) return;
  if (role == QueryRole::kStore) {
    placement_->Store(RobotId(q.robot), FrameId(q.frame), q.descriptor.data());
    return;
  }
  EnqueueSearch(RobotId(q.robot), FrameId(q.frame), role == QueryRole::kSearchAndStore, [&](DescriptorSearch& job) {
    job.descriptor = q.descriptor.data();
    job.message = message;
  });
}

void RobotAgent::OnMatch(const match_t& m) {
  if (!online_ || m.query_robot != id_.value || LocalIndexOf(FrameId(m.query_frame)) < 0) return;
  if (!ReplyFromTeam(m.responder, m.has_match, m.match_robot)) return;
  std::optional<IndexMatch> match;
  if (m.has_match) match = IndexMatch{RobotId(m.match_robot), FrameId(m.match_frame), m.distance};
  RecordReply(FrameId(m.query_frame), RobotId(m.responder), match);
}

// Ties keep the earlier reply, so the outcome does not depend on arrival order only through
// equal distances.
void RobotAgent::RecordReply(FrameId frame, RobotId responder, const std::optional<IndexMatch>& match) {
  const int k = AcceptReply(frame, responder);
  if (k < 0) return;
  QueryRecord& o = Record(k);
  if (match && (!o.best || match->distance < o.best->distance)) o.best = match;
  Replied(k);
}

}  // namespace dvpr
