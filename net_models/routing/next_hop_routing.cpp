#include "net_models/routing/next_hop_routing.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dvpr {

NextHopKind ParseNextHopKind(std::string_view name) {
  if (name == "direct") return NextHopKind::kDirect;
  if (name == "shortest_path") return NextHopKind::kShortestPath;
  if (name == "link_state") return NextHopKind::kLinkState;
  throw std::invalid_argument("unknown value '" + std::string(name) +
                              "' (expected one of: direct, shortest_path, link_state)");
}

std::string_view ToString(NextHopKind kind) {
  switch (kind) {
    case NextHopKind::kDirect: return "direct";
    case NextHopKind::kShortestPath: return "shortest_path";
    case NextHopKind::kLinkState: return "link_state";
  }
  return "unknown";
}

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
