#pragma once
// One copy of a message on its way through a network (forwarder.h, transmission_ledger.h).
#include <cstdint>

#include "net_models/core/node_id.h"
#include "sim/sim_time.h"

namespace dvpr {

// A copy on its way: where to, the node it arrives at next (dst, or a relay), its number
// (MessageCopy::copy), the transmissions it has made (the one under way included), whether a
// robot has held it (store-and-forward: RouteCounters::held counts a copy once, however many
// robots and retries hold it), when it arrives there. 48 bits number 2.8e14 copies; hops stay
// <= Forwarder::kMaxHops.
struct PendingCopy {
  NodeId dst;
  NodeId at;
  std::uint64_t copy : 48;
  std::uint64_t hops : 15;
  std::uint64_t held : 1;
  SimTime arrival;
};
static_assert(sizeof(PendingCopy) <= 24);

}  // namespace dvpr
