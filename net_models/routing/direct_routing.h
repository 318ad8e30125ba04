#pragma once
// "direct": every copy goes straight to its destination in one hop, the full mesh's routing and
// dvpr's default. With a propagation model that does not reach, such a copy is dropped out of
// range (no relay takes it on).
#include "net_models/routing/next_hop_routing.h"

namespace dvpr {

class DirectNextHop final : public NextHopRouting {
 private:
  // Every hop arrives preset to its destination: nothing to change.
  void DoNextHops(NodeId, std::span<const NodeId>, SimTime, std::span<NodeId>) override {}
  std::string_view DoName() const override { return "direct"; }
};

}  // namespace dvpr
