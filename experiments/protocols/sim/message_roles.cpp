#include "experiments/protocols/sim/message_roles.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "agents/channels.h"
#include "agents/recluster/recluster_messages.h"

namespace dvpr {

namespace {

// A unicast channel's name without its destination id ("DVPR_QUERY_"): taken from the channel
// functions themselves, so a renamed channel cannot fall out of its role unnoticed.
std::string PrefixOf(const std::string& channel_of_robot_0) {
  return channel_of_robot_0.substr(0, channel_of_robot_0.size() - 1);
}

bool StartsWith(std::string_view s, const std::string& prefix) { return s.substr(0, prefix.size()) == prefix; }

}  // namespace

MessageRole RoleOfChannel(std::string_view channel) {
  const RobotId r0(0);
  // DVPR_QUERY_ALL starts with the prefix of DVPR_QUERY_<n>: a query too.
  static const std::string query = PrefixOf(channels::Query(r0));
  static const std::string probe = PrefixOf(channels::Probe(r0));
  static const std::string store = PrefixOf(channels::Store(r0));
  static const std::string match = PrefixOf(channels::Match(r0));
  static const std::string vreq = PrefixOf(channels::VerifyRequest(r0));
  static const std::string vres = PrefixOf(channels::VerifyResult(r0));
  static const std::string sample = PrefixOf(channels::Sample(r0));
  static const std::string migrate = PrefixOf(channels::Migrate(r0));
  static const std::string bow_query = PrefixOf(channels::BowQuery(r0));
  static const std::string bow_probe = PrefixOf(channels::BowProbe(r0));
  static const std::string bow_match = PrefixOf(channels::BowMatch(r0));
  if (StartsWith(channel, query) || StartsWith(channel, probe) || StartsWith(channel, store) ||
      StartsWith(channel, bow_query) || StartsWith(channel, bow_probe)) {
    return MessageRole::kQuery;
  }
  if (StartsWith(channel, match) || StartsWith(channel, bow_match)) return MessageRole::kReply;
  if (StartsWith(channel, vreq)) return MessageRole::kVerifyRequest;
  if (StartsWith(channel, vres)) return MessageRole::kVerifyResult;
  if (StartsWith(channel, sample) || StartsWith(channel, migrate) || channel == channels::kTable) {
    return MessageRole::kRecluster;
  }
  return MessageRole::kOther;
}

RoleBytesRecorder::RoleBytesRecorder(int nodes) : nodes_(nodes) {
  if (nodes <= 0) throw std::invalid_argument("RoleBytesRecorder: need at least one node, got " + std::to_string(nodes));
}

RoleCopyBytes RoleBytesRecorder::Pair(int src, int dst) const {
  RoleCopyBytes bytes{};
  for (std::size_t r = 0; r < bytes.size(); ++r) {
    if (by_role_[r] == nullptr) continue;
    if (const CopyBytes* c = by_role_[r]->Find(NodeId(src), NodeId(dst))) bytes[r] = *c;
  }
  return bytes;
}

std::vector<std::pair<int, int>> RoleBytesRecorder::PairsSorted() const {
  std::vector<std::pair<int, int>> pairs;
  for (const auto& table : by_role_) {
    if (table == nullptr) continue;
    table->ForEachSorted([&pairs](NodeId src, NodeId dst, const CopyBytes&) { pairs.emplace_back(src.value, dst.value); });
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

CopyBytes& RoleBytesRecorder::At(std::size_t role, NodeId src, NodeId dst) {
  auto& table = by_role_[role];
  if (table == nullptr) table = std::make_unique<PairMap<CopyBytes>>(nodes_);
  return table->At(src, dst);
}

std::size_t RoleBytesRecorder::RoleIndex(ChannelId channel, std::string_view name) {
  const auto id = static_cast<std::size_t>(channel);
  if (id >= roles_.size()) roles_.resize(id + 1, -1);
  if (roles_[id] < 0) roles_[id] = static_cast<std::int8_t>(RoleOfChannel(name));
  return static_cast<std::size_t>(roles_[id]);
}

void RoleBytesRecorder::OnSent(const MessageCopy& copy) {
  CopyBytes& c = At(RoleIndex(copy.channel, copy.channel_name), copy.src, copy.dst);
  c.payload += static_cast<std::int64_t>(copy.payload.size());
  c.wire += copy.wire_bytes;
}

void RoleBytesRecorder::OnDelivered(const MessageCopy& copy, SimTime) {
  CopyBytes& c = At(RoleIndex(copy.channel, copy.channel_name), copy.src, copy.dst);
  c.delivered_payload += static_cast<std::int64_t>(copy.payload.size());
  c.delivered_wire += copy.wire_bytes;
}

void RoleBytesRecorder::OnMedium(const MediumReport& use) {
  medium_[RoleIndex(use.channel, use.channel_name)] += use.bytes;
}

RunRoleBytes RoleBytesRecorder::Run() const {
  RunRoleBytes run;
  run.medium = medium_;
  for (std::size_t r = 0; r < by_role_.size(); ++r) {
    if (by_role_[r] != nullptr) by_role_[r]->ForEach([&run, r](const CopyBytes& c) { run.copies[r] += c; });
  }
  return run;
}

}  // namespace dvpr
