#pragma once
// What a message does, read from its channel name alone (agents/channels.h,
// agents/recluster/recluster_messages.h), so a replay needs nothing but
// messages.csv: the page colours each message by it and counts a robot's
// queue from the requests it got and the answers it sent.
#include <string_view>

#include "experiments/results/results.h"

namespace dvpr::replay {

// The roles are the result files' own (results.h, MessageRole): query = DVPR_QUERY_*,
// DVPR_PROBE_*, DVPR_STORE_*, DVPR_QUERY_ALL; reply = DVPR_MATCH_*; verify request =
// DVPR_VREQ_*; verify result = DVPR_VRES_*; recluster = DVPR_SAMPLE_*, DVPR_TABLE,
// DVPR_MIGRATE_*; other = any other channel (a later protocol's), drawn grey.
using dvpr::kMessageRoles;
using dvpr::MessageRole;

// How a message moves its receiver's queue: a request waits there until the
// receiver sends its answer (a store-only query and re-clustering are neither).
enum class QueueEffect { kNone = 0, kRequest = 1, kAnswer = -1 };

MessageRole RoleOfChannel(std::string_view channel);
QueueEffect QueueEffectOfChannel(std::string_view channel);
// The role's name on the page ("query", "reply", "verify request", ...).
std::string_view RoleName(MessageRole role);

}  // namespace dvpr::replay
