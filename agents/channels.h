#pragma once
// Channel names. One LCM type per channel; unicast channels carry the
// destination robot's id, broadcast queries share one channel.
//
// A query's channel tells its receiver what to do with it (QueryRole), so a
// responder never re-derives that from the sender's routing. The three
// unicast query prefixes have the same length: a channel name is counted in
// the wire bytes (docs/design.md section 4), so the role costs no byte.
#include <string>

#include "agents/ids.h"

namespace dvpr {

// What the receiver of a query does with it.
enum class QueryRole {
  kSearchAndStore,  // search the store, reply, then keep the query (the paper's owner)
  kSearch,          // search and reply only (a probe; every robot of the broadcast baseline)
  kStore,           // keep it without searching or replying (a boundary replica)
};

namespace channels {

inline std::string Query(RobotId dst) { return "DVPR_QUERY_" + std::to_string(dst.value); }
inline std::string Probe(RobotId dst) { return "DVPR_PROBE_" + std::to_string(dst.value); }
inline std::string Store(RobotId dst) { return "DVPR_STORE_" + std::to_string(dst.value); }
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
// robot keeps its own frame. The name predates the roles and stays: it is counted in the bytes.
inline const std::string kQueryAll = "DVPR_QUERY_ALL";
inline std::string Match(RobotId dst) { return "DVPR_MATCH_" + std::to_string(dst.value); }
inline std::string VerifyRequest(RobotId dst) { return "DVPR_VREQ_" + std::to_string(dst.value); }
inline std::string VerifyResult(RobotId dst) { return "DVPR_VRES_" + std::to_string(dst.value); }
// The bag-of-words strategies (docs/bow.md, agents/bow_robot_agent.h): a partial query (bow_query_t)
// its receiver scores and then stores (the distributed inverted index, the centralized server),
// one it only scores (bow_broadcast: every robot keeps its own frames), and the reply
// (bow_match_t). Prefixes of one length, like the descriptor queries'.
inline std::string BowQuery(RobotId dst) { return "DVPR_BOWQ_" + std::to_string(dst.value); }
inline std::string BowProbe(RobotId dst) { return "DVPR_BOWP_" + std::to_string(dst.value); }
inline std::string BowMatch(RobotId dst) { return "DVPR_BOWM_" + std::to_string(dst.value); }

}  // namespace channels
}  // namespace dvpr
