#include "net_models/core/transmission.h"

namespace dvpr {

std::string_view ToString(DropReason reason) {
  switch (reason) {
    case DropReason::kNone: return "none";
    case DropReason::kQueueFull: return "queue_full";
    case DropReason::kLoss: return "loss";
    case DropReason::kOffline: return "offline";
    case DropReason::kNoRoute: return "no_route";
    case DropReason::kOutOfRange: return "out_of_range";
    case DropReason::kHopLimit: return "hop_limit";
    case DropReason::kBufferFull: return "buffer_full";
    case DropReason::kExpired: return "expired";
    case DropReason::kStaleRoute: return "stale_route";
    case DropReason::kRetryLimit: return "retry_limit";
    case DropReason::kCollision: return "collision";
  }
  return "unknown";
}

}  // namespace dvpr
