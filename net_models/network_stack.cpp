#include "net_models/network_stack.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "net_models/direct_routing.h"
#include "net_models/fixed_mobility.h"
#include "net_models/full_mesh_propagation.h"

namespace dvpr {

void NetworkStack::CompleteDefaults(int nodes) {
  if (!access) throw std::invalid_argument("NetworkStack: no medium access (link) model");
  if (!mobility) mobility = std::make_unique<FixedMobility>(FixedMobility::AtOrigin(nodes));
  if (mobility->nodes() != nodes) {
    throw std::invalid_argument("NetworkStack: the mobility model places " + std::to_string(mobility->nodes()) +
                                " nodes, the network has " + std::to_string(nodes));
  }
  if (!propagation) propagation = std::make_unique<FullMeshPropagation>();
  if (!routing) routing = std::make_unique<DirectRouting>();
}

NetworkStack MakeNetworkStack(const NetworkModelParams& params, int nodes, std::uint64_t run_seed,
                              std::unique_ptr<MobilityModel> mobility) {
  NetworkStack stack;
  stack.mobility = std::move(mobility);
  stack.access = MakeLinkModel(params, nodes, run_seed);
  stack.CompleteDefaults(nodes);
  return stack;
}

}  // namespace dvpr
