#pragma once
// What a message does. Every channel has exactly one role (channels.h), so bytes counted by role
// sum to the totals; the result files' byte columns by role follow this order (results.h).
namespace dvpr {

enum class MessageRole : int {
  kQuery,          // a place-recognition query (search, store or both; broadcast or unicast)
  kReply,          // its reply, the best match (match_t, bow_match_t)
  kVerifyRequest,  // geometric-verification request
  kVerifyResult,   // its accept/reject
  kRecluster,      // adaptive re-clustering: samples, tables, migrated descriptors
  kOther,          // any other channel (heartbeats, a channel no catalogue entry names)
};
inline constexpr int kMessageRoles = 6;

}  // namespace dvpr
