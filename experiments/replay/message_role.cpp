#include "experiments/replay/message_role.h"

namespace dvpr::replay {

QueueEffect QueueEffectOfChannel(std::string_view c) {
  const auto kind = channels::KindOf(c);
  if (!kind) return QueueEffect::kNone;
  const channels::ChannelSpec& spec = channels::SpecOf(*kind);
  if (spec.request) return QueueEffect::kRequest;
  return spec.answer ? QueueEffect::kAnswer : QueueEffect::kNone;
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
