#pragma once
// Bytes by message role (MessageRole), counted from a Network's hooks: the role of a message is
// read from its channel in the message catalogue (lcmtypes/channels/channels.h), so no agent has
// to say what it sent, and the network stays the only byte counter.
//
// Per directed pair and role: the copies' payload and wire bytes, offered (every copy sent) and
// delivered; per role: what the messages put on the medium (MediumReport), so the roles sum to
// the run's wire_bytes also on a shared medium, where a broadcast is one transmission.
#include <array>
#include <cstdint>
#include <memory>
#include <string_view>
#include <utility>
#include <vector>

#include "experiments/results/results.h"
#include "net_models/core/pair_map.h"
#include "net_models/network/network_observer.h"

namespace dvpr {

// Per role, a table of the pairs (PairMap<CopyBytes>, made when the role is first seen): a copy
// touches 32 bytes of its role's table, and the copies of one broadcast (one source, destinations
// in order) or of one robot's replies lie side by side in it. One 192-byte entry per pair with
// every role in it made each copy a cache line of its own (a tenth of the 100-robot broadcast).
class RoleBytesRecorder : public NetworkObserver {
 public:
  explicit RoleBytesRecorder(int nodes);
  void OnSent(const MessageCopy& copy) override;
  void OnDelivered(const MessageCopy& copy, SimTime at) override;
  void OnMedium(const MediumReport& use) override;

  // The pair src -> dst (all zero for a pair that carried nothing).
  RoleCopyBytes Pair(int src, int dst) const;
  // Calls f(src, dst, bytes) for every pair that carried a message, by source, then destination.
  template <class F>
  void ForEachPair(F&& f) const {
    for (const auto& [src, dst] : PairsSorted()) f(NodeId(src), NodeId(dst), Pair(src, dst));
  }
  // Summed over every pair, with the medium bytes.
  RunRoleBytes Run() const;

 private:
  // The role of an interned channel, classified once per channel.
  std::size_t RoleIndex(ChannelId channel, std::string_view name);
  // The pair's bytes of the role; the role's table is made on first use.
  CopyBytes& At(std::size_t role, NodeId src, NodeId dst);
  std::vector<std::pair<int, int>> PairsSorted() const;

  int nodes_;
  std::array<std::unique_ptr<PairMap<CopyBytes>>, kMessageRoles> by_role_;  // only the pairs that carried it
  std::array<std::int64_t, kMessageRoles> medium_{};
  std::vector<std::int8_t> roles_;  // by ChannelId; -1: not yet seen
};

}  // namespace dvpr
