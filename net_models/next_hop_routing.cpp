#include "net_models/next_hop_routing.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dvpr {

void NextHopRouting::NextHops(NodeId at, std::span<const NodeId> dsts, SimTime now, int nodes,
                              std::span<NodeId> hops) {
  if (hops.size() != dsts.size()) throw std::logic_error("NextHopRouting::NextHops: one hop slot per destination expected");
  std::copy(dsts.begin(), dsts.end(), hops.begin());
  DoNextHops(at, dsts, now, hops);
  for (std::size_t i = 0; i < hops.size(); ++i) {
    const NodeId hop = hops[i];
    if (hop == kNoRoute || hop == dsts[i]) continue;
    if (hop == at || hop.value < 0 || hop.value >= nodes) {
      throw std::logic_error("NextHopRouting '" + std::string(Name()) + "': next hop " + std::to_string(hop.value) +
                             " from node " + std::to_string(at.value) + " to " + std::to_string(dsts[i].value) +
                             " is not a neighbour in [0, " + std::to_string(nodes) + ")");
    }
  }
}

}  // namespace dvpr
