#pragma once
// The agents' channels by robot id. The names, the LCM type each carries and each channel's
// role live in the message catalogue (lcmtypes/channels/channels.h); these are its typed doors.
//
// A query's channel tells its receiver what to do with it (QueryRole), so a responder never
// re-derives that from the sender's routing.
#include <string>

#include "agents/algorithms/ids.h"
#include "lcmtypes/channels/channels.h"

namespace dvpr {

// What the receiver of a query does with it.
enum class QueryRole {
  kSearchAndStore,  // search the store, reply, then keep the query (the paper's owner)
  kSearch,          // search and reply only (a probe; every robot of the broadcast baseline)
  kStore,           // keep it without searching or replying (a boundary replica)
};

namespace channels {

inline std::string Query(RobotId dst) { return ChannelName(ChannelKind::kQuery, dst.value); }
inline std::string Probe(RobotId dst) { return ChannelName(ChannelKind::kProbe, dst.value); }
inline std::string Store(RobotId dst) { return ChannelName(ChannelKind::kStore, dst.value); }
// The query channel of `dst` for `role`.
inline std::string QueryTo(RobotId dst, QueryRole role) {
  switch (role) {
    case QueryRole::kSearchAndStore: return Query(dst);
    case QueryRole::kSearch: return Probe(dst);
    case QueryRole::kStore: return Store(dst);
  }
  return Query(dst);
}
// The broadcast baseline's queries: every receiver searches (QueryRole::kSearch); the querying
// robot keeps its own frame.
inline const std::string kQueryAll = ChannelName(ChannelKind::kQueryAll);
inline std::string Match(RobotId dst) { return ChannelName(ChannelKind::kMatch, dst.value); }
inline std::string VerifyRequest(RobotId dst) { return ChannelName(ChannelKind::kVerifyRequest, dst.value); }
inline std::string VerifyResult(RobotId dst) { return ChannelName(ChannelKind::kVerifyResult, dst.value); }
// The bag-of-words strategies (docs/bow.md, agents/bow_robot_agent.h): a partial query (bow_query_t)
// its receiver scores and then stores (the distributed inverted index, the centralized server),
// one it only scores (bow_broadcast: every robot keeps its own frames), and the reply
// (bow_match_t).
inline std::string BowQuery(RobotId dst) { return ChannelName(ChannelKind::kBowQuery, dst.value); }
inline std::string BowProbe(RobotId dst) { return ChannelName(ChannelKind::kBowProbe, dst.value); }
inline std::string BowMatch(RobotId dst) { return ChannelName(ChannelKind::kBowMatch, dst.value); }
// link_state routing's beacons (net_models/link_state/daemon/link_state_daemon.h): link-local, the team's channels.
inline const std::string kHello = ChannelName(ChannelKind::kHello);
inline const std::string kTopology = ChannelName(ChannelKind::kTopology);

}  // namespace channels
}  // namespace dvpr
