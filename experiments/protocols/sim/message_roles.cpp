#include "experiments/protocols/sim/message_roles.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "lcmtypes/channels/channels.h"

namespace dvpr {

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
  if (roles_[id] < 0) roles_[id] = static_cast<std::int8_t>(channels::RoleOf(name));
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
