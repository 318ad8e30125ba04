#pragma once
// The message catalogue: every channel dvpr's agents publish on, the LCM type it carries and
// what its receiver does with it. The one home of the channel names: the agents name their
// channels through it (agents/messages/channels.h, agents/recluster/recluster_messages.h,
// agents/messages/team_sync.h), and the simulation's recorders, the LCM agent process and `dvpr replay`
// read a channel's role from it, so the four cannot drift apart.
//
// A unicast channel is a prefix and the receiving robot's id ("<prefix>3"); the others are one
// name for the whole team. The query prefixes of one family have the same length: the channel
// name is counted in the wire bytes (docs/design.md section 4), so the role a prefix gives costs
// no byte.
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "lcmtypes/channels/message_role.h"

namespace dvpr::channels {

enum class ChannelKind : int {
  kQuery,          // query_t to search, reply, then store (the paper's owner)
  kProbe,          // query_t to search and reply only (a probe)
  kStore,          // query_t to store only, never answered (a boundary replica)
  kQueryAll,       // query_t to every robot, each searches (the broadcast baseline)
  kMatch,          // match_t, the reply to a query
  kVerifyRequest,  // verify_request_t, to the robot that took the matched frame
  kVerifyResult,   // verify_result_t, its answer
  kBowQuery,       // bow_query_t, a partial bag-of-words query to score, reply, then store
  kBowProbe,       // bow_query_t to score and reply only (bow_broadcast)
  kBowMatch,       // bow_match_t, the reply to a partial query
  kSample,         // descriptor_batch_t, a robot's sample of an epoch, to the leader
  kMigrate,        // descriptor_batch_t, stored descriptors moved to their new owner
  kTable,          // centroid_table_t, the leader's table of an epoch, to every robot
  kStatus,         // agent_status_t, every agent's heartbeat (start barrier, failover)
  kHello,          // routing_hello_t, link_state routing's beacon to the robots in range
  kTopology,       // routing_topology_t, link_state routing's flooded topology
};
inline constexpr int kChannelKinds = 16;

struct ChannelSpec {
  ChannelKind kind;
  std::string_view name;  // the whole name, or a unicast channel's prefix
  bool unicast;           // name + the receiving robot's id
  MessageRole role;
  bool request;  // its receiver owes an answer (it waits in the receiver's queue until then)
  bool answer;   // it answers a request
};

// Every channel, in ChannelKind order.
std::span<const ChannelSpec> AllChannels();
const ChannelSpec& SpecOf(ChannelKind kind);
// The LCM type a channel carries, as lcm-gen names it ("query_t", lcmtypes/dvpr/query_t.lcm).
std::string_view LcmTypeOf(ChannelKind kind);

// The channel of `kind` to robot `robot` (unicast), or the team's channel (robot < 0); throws
// std::invalid_argument when the two do not fit (a unicast kind without a robot or the reverse).
std::string ChannelName(ChannelKind kind, int robot = -1);

// The kind of a channel: a team channel by its whole name, a unicast one by its prefix (what
// follows the prefix is not read: a reply's prefix followed by "3" or by "x" is a reply). Empty
// for a channel the catalogue does not name.
std::optional<ChannelKind> KindOf(std::string_view channel);
// The role of a channel; MessageRole::kOther for one the catalogue does not name.
MessageRole RoleOf(std::string_view channel);

}  // namespace dvpr::channels
