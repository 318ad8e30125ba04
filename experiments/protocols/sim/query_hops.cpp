#include "experiments/protocols/sim/query_hops.h"

#include "lcmtypes/channels/channels.h"

namespace dvpr {

namespace {

// Robot ids are int16 on the wire, frame ids int32.
std::uint64_t QueryKey(int robot, std::int32_t frame) {
  return (static_cast<std::uint64_t>(static_cast<std::uint16_t>(robot)) << 32) | static_cast<std::uint32_t>(frame);
}

std::uint64_t RequestKey(int robot, std::int32_t frame, int receiver) {
  return QueryKey(robot, frame) | (static_cast<std::uint64_t>(static_cast<std::uint16_t>(receiver)) << 48);
}

}  // namespace

void QueryHopsRecorder::OnDelivered(const MessageCopy& copy, SimTime) {
  using channels::ChannelKind;
  const std::optional<ChannelKind> kind = channels::KindOf(copy.channel_name);
  if (!kind) return;
  switch (*kind) {
    case ChannelKind::kQuery:
    case ChannelKind::kProbe:
    case ChannelKind::kQueryAll:
      if (DecodeInto(copy.payload, query_)) OnRequest(query_.robot, query_.frame, copy);
      return;
    case ChannelKind::kBowQuery:
    case ChannelKind::kBowProbe:
      if (DecodeInto(copy.payload, bow_query_)) OnRequest(bow_query_.robot, bow_query_.frame, copy);
      return;
    case ChannelKind::kMatch:
      if (DecodeInto(copy.payload, match_)) OnReply(match_);
      return;
    case ChannelKind::kBowMatch:
      if (DecodeInto(copy.payload, bow_match_)) OnReply(bow_match_);
      return;
    default:
      return;
  }
}

void QueryHopsRecorder::OnRequest(int robot, std::int32_t frame, const MessageCopy& copy) {
  request_hops_.try_emplace(RequestKey(robot, frame, copy.dst.value), copy.hops);
}

template <typename Match>
void QueryHopsRecorder::OnReply(const Match& m) {
  if (!m.has_match) return;
  replies_[QueryKey(m.query_robot, m.query_frame)].push_back(Reply{m.responder, m.match_robot, m.match_frame});
}
std::optional<int> QueryHopsRecorder::HopsOf(const QueryRecord& q) const {
  if (!q.best) return std::nullopt;
  const auto replies = replies_.find(QueryKey(q.robot.value, q.frame.value));
  if (replies != replies_.end()) {
    for (const Reply& r : replies->second) {
      if (r.match_robot != q.best->robot.value || r.match_frame != q.best->frame.value) continue;
      const auto hops = request_hops_.find(RequestKey(q.robot.value, q.frame.value, r.responder));
      if (hops == request_hops_.end()) return std::nullopt;  // a reply to a query it never got
      return hops->second;
    }
  }
  return 0;  // no reply named it: the robot's own search
}

}  // namespace dvpr
