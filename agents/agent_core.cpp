#include "agents/agent_core.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "agents/messages/channels.h"
#include "agents/messages/verification_payload.h"

namespace dvpr {

void AgentSetup::Validate(const std::string& agent) const {
  params.Validate();
  if (robots < 1 || id.value < 0 || id.value >= robots) {
    throw std::invalid_argument(agent + ": robot " + std::to_string(id.value) + " is not in a team of " +
                                std::to_string(robots));
  }
  if (!(frames.fps > 0.0)) throw std::invalid_argument(agent + ": fps must be positive");
  if (frames.count < 0) throw std::invalid_argument(agent + ": a negative frame count");
  if (!frames.times.empty() && frames.times.size() != static_cast<std::size_t>(frames.count)) {
    throw std::invalid_argument(agent + ": " + std::to_string(frames.times.size()) + " capture times for " +
                                std::to_string(frames.count) + " frames");
  }
  if (!std::is_sorted(frames.times.begin(), frames.times.end()) ||
      (!frames.times.empty() && frames.times.front() < SimTime::Zero())) {
    throw std::invalid_argument(agent + ": capture times must be ascending from 0 on");
  }
  if (!std::is_sorted(window_streams.begin(), window_streams.end()) ||
      (!window_streams.empty() && window_streams.front().value <= 0)) {
    throw std::invalid_argument(agent + ": window streams must begin at ascending frames after 0");
  }
}

AgentCore::AgentCore(const AgentSetup& setup, double verify_max_distance, Transport& transport,
                     GeometricVerifier verifier)
    : id_(setup.id),
      transport_(transport),
      params_(setup.params),
      window_(setup.params.suppression_frames, setup.window_streams),
      robots_(setup.robots),
      verify_max_distance_(static_cast<float>(verify_max_distance)),
      records_(std::make_unique<Records>()) {
  setup.Validate("agent");
  records_->frames = setup.frames;
  records_->verifier = std::move(verifier);
  records_->outcomes.resize(static_cast<std::size_t>(setup.frames.count));
  records_->responded.resize(static_cast<std::size_t>(setup.frames.count));
}

RobotLoad AgentCore::load() const {
  RobotLoad load = load_;
  load.stored = Stored();
  return load;
}

std::vector<std::string> AgentCore::VerificationChannels(RobotId id) {
  return {channels::VerifyRequest(id), channels::VerifyResult(id)};
}

// The task in service, if any, ends without effect (its end checks online_).
void AgentCore::GoOffline() {
  online_ = false;
  DropWaiting();
  Stopped();
}

void AgentCore::SubscribeVerification() {
  Keep(transport_.Subscribe<verify_request_t>(channels::VerifyRequest(id_),
                                              [this](const verify_request_t& r) { OnVerifyRequest(r); }));
  Keep(transport_.Subscribe<verify_result_t>(channels::VerifyResult(id_),
                                             [this](const verify_result_t& r) { OnVerifyResult(r); }));
}

void AgentCore::StartClock() {
  if (records_->frames.count > 0) transport_.ScheduleAfter(records_->frames.TimeOf(0), [this] { Tick(0); });
}

void AgentCore::Tick(int k) {
  if (!online_) return;
  if (k + 1 < records_->frames.count) {
    transport_.ScheduleAfter(records_->frames.TimeOf(k + 1) - records_->frames.TimeOf(k), [this, k] { Tick(k + 1); });
  }
  TakeFrame(k);
}

QueryRecord& AgentCore::BeginQuery(int k, int expected_replies) {
  QueryRecord& o = Record(k);
  o.robot = id_;
  o.frame = FrameAt(k);
  o.sent = transport_.Now();
  o.expected_replies = expected_replies;
  return o;
}

int AgentCore::LocalIndexOf(FrameId frame) const {
  const int k = frame.value - records_->frames.first.value;
  return (k >= 0 && k < records_->frames.count) ? k : -1;
}

bool AgentCore::Foreign(int robot) {
  if (robot >= 0 && robot < robots_) return false;
  ++load_.foreign_ids;
  return true;
}

bool AgentCore::ReplyFromTeam(int responder, bool has_match, int match_robot) {
  return !Foreign(responder) && !(has_match && Foreign(match_robot));
}

int AgentCore::AcceptReply(FrameId frame, RobotId responder) {
  const int k = LocalIndexOf(frame);
  if (k < 0) return -1;
  QueryRecord& o = Record(k);
  if (o.received_replies >= o.expected_replies) return -1;  // late, or a frame not taken
  std::vector<std::uint64_t>& seen = records_->responded[static_cast<std::size_t>(k)];
  if (seen.empty()) seen.assign(static_cast<std::size_t>(robots_ + 63) / 64, 0);
  const auto r = static_cast<std::size_t>(responder.value);
  const std::uint64_t bit = std::uint64_t{1} << (r % 64);
  if ((seen[r / 64] & bit) != 0) return -1;  // a duplicate (real networks)
  seen[r / 64] |= bit;
  ++o.received_replies;
  return k;
}

void AgentCore::Replied(int k) {
  QueryRecord& o = Record(k);
  if (!o.Complete()) return;
  o.latency = transport_.Now() - o.sent;
  records_->responded[static_cast<std::size_t>(k)] = {};
  Conclude(k);
  MaybeVerify(k);
}

void AgentCore::MaybeVerify(int k) {
  QueryRecord& o = Record(k);
  if (!o.best || o.best->distance > verify_max_distance_) return;
  o.verify_requested = true;
  if (o.best->robot == id_) {
    EnqueueVerify(id_, o.frame, o.best->frame);
    return;
  }
  verify_request_t& r = records_->verify_request;
  FillVerifyRequest(r, transport_.Utime(), id_, o.frame, o.best->robot, o.best->frame,
                    static_cast<std::int32_t>(params_.verification.request_bytes.value()));
  FillVerificationPayload(o.frame, VerificationFeatures(o.frame), r.payload);
  transport_.Publish(ChannelOf(records_->verify_request_channels, o.best->robot, channels::VerifyRequest), r);
}

void AgentCore::OnVerifyRequest(const verify_request_t& r) {
  if (!online_ || r.match_robot != id_.value || Foreign(r.query_robot)) return;
  EnqueueVerify(RobotId(r.query_robot), FrameId(r.query_frame), FrameId(r.match_frame));
}

void AgentCore::OnVerifyResult(const verify_result_t& r) {
  if (!online_) return;
  const int k = LocalIndexOf(FrameId(r.query_frame));
  if (r.query_robot != id_.value || k < 0) return;
  Record(k).verify_accepted = r.accepted;
}

void AgentCore::FinishVerification(RobotId querier, FrameId frame, FrameId match_frame) {
  const VerifyVerdict verdict = records_->verifier(frame, match_frame);
  if (querier == id_) {
    Record(LocalIndexOf(frame)).verify_accepted = verdict.accepted;
  } else {
    transport_.Publish(ChannelOf(records_->verify_result_channels, querier, channels::VerifyResult),
                       MakeVerifyResult(transport_.Utime(), querier, frame, id_, match_frame, verdict));
  }
}

// Interned once per robot instead of named and looked up once per message. Ids come from int16
// fields of the wire, so a table stays below 32768 entries; a negative one (garbage) is
// interned by name each time (the transport keeps one entry a name).
PublishChannel AgentCore::ChannelOf(std::vector<std::uint32_t>& by_robot, RobotId robot,
                                    std::string (*name)(RobotId)) {
  if (robot.value < 0) return transport_.Intern(name(robot));
  const auto i = static_cast<std::size_t>(robot.value);
  if (i >= by_robot.size()) by_robot.resize(i + 1, kNoChannel);
  if (by_robot[i] == kNoChannel) by_robot[i] = static_cast<std::uint32_t>(transport_.Intern(name(robot)));
  return PublishChannel{by_robot[i]};
}

}  // namespace dvpr
