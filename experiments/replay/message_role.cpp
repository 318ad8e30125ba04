#include "experiments/replay/message_role.h"

namespace dvpr::replay {

namespace {

bool Starts(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

}  // namespace

MessageRole RoleOfChannel(std::string_view c) {
  if (Starts(c, "DVPR_QUERY_") || Starts(c, "DVPR_PROBE_") || Starts(c, "DVPR_STORE_")) return MessageRole::kQuery;
  // The bag-of-words strategies' partial queries and replies (agents/channels.h, docs/bow.md).
  if (Starts(c, "DVPR_BOWQ_") || Starts(c, "DVPR_BOWP_")) return MessageRole::kQuery;
  if (Starts(c, "DVPR_MATCH_") || Starts(c, "DVPR_BOWM_")) return MessageRole::kReply;
  if (Starts(c, "DVPR_VREQ_")) return MessageRole::kVerifyRequest;
  if (Starts(c, "DVPR_VRES_")) return MessageRole::kVerifyResult;
  if (Starts(c, "DVPR_SAMPLE_") || Starts(c, "DVPR_MIGRATE_") || c == "DVPR_TABLE") return MessageRole::kRecluster;
  return MessageRole::kOther;
}

QueueEffect QueueEffectOfChannel(std::string_view c) {
  if (Starts(c, "DVPR_STORE_")) return QueueEffect::kNone;  // kept without a search or a reply
  switch (RoleOfChannel(c)) {
    case MessageRole::kQuery:
    case MessageRole::kVerifyRequest: return QueueEffect::kRequest;
    case MessageRole::kReply:
    case MessageRole::kVerifyResult: return QueueEffect::kAnswer;
    default: return QueueEffect::kNone;
  }
}

std::string_view RoleName(MessageRole role) {
  switch (role) {
    case MessageRole::kQuery: return "query";
    case MessageRole::kReply: return "reply";
    case MessageRole::kVerifyRequest: return "verify request";
    case MessageRole::kVerifyResult: return "verify result";
    case MessageRole::kRecluster: return "re-clustering";
    case MessageRole::kOther: break;
  }
  return "other";
}

}  // namespace dvpr::replay
