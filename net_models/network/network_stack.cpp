#include "net_models/network/network_stack.h"

#include <stdexcept>
#include <string>

#include "net_models/mobility/fixed_mobility.h"
#include "net_models/propagation/full_mesh_propagation.h"
#include "net_models/routing/direct_routing.h"

namespace dvpr {

void NetworkStack::CompleteDefaults(int nodes) {
  if (nodes <= 0) throw std::invalid_argument("robots = " + std::to_string(nodes) + ": need at least one node");
  if (!access) throw std::invalid_argument("NetworkStack: no medium access (link) model");
  if (!mobility) mobility = std::make_unique<FixedMobility>(FixedMobility::AtOrigin(nodes));
  if (mobility->nodes() != nodes) {
    throw std::invalid_argument("NetworkStack: the mobility model places " + std::to_string(mobility->nodes()) +
                                " nodes, the network has " + std::to_string(nodes));
  }
  if (!propagation) propagation = std::make_unique<FullMeshPropagation>();
  if (!next_hop) next_hop = std::make_unique<DirectNextHop>();
}

}  // namespace dvpr
