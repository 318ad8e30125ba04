#pragma once
// What a message does, read from its channel name alone in the message catalogue
// (lcmtypes/channels/channels.h: its role, whether it is a request or an answer), so a replay
// needs nothing but messages.csv: the page colours each message by its role and counts a
// robot's queue from the requests it got and the answers it sent.
#include <string_view>

#include "lcmtypes/channels/channels.h"

namespace dvpr::replay {

// The roles are the result files' own (MessageRole); a channel the catalogue does not name (a
// later protocol's) is "other", drawn grey.
using dvpr::kMessageRoles;
using dvpr::MessageRole;

// How a message moves its receiver's queue: a request waits there until the
// receiver sends its answer (a store-only query and re-clustering are neither).
enum class QueueEffect { kNone = 0, kRequest = 1, kAnswer = -1 };

QueueEffect QueueEffectOfChannel(std::string_view channel);
// The role's name on the page ("query", "reply", "verify request", ...).
std::string_view RoleName(MessageRole role);

}  // namespace dvpr::replay
