#include "net_models/helper/network_helper.h"

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "net_models/mobility/fixed_mobility.h"
#include "net_models/propagation/propagation_registry.h"
#include "net_models/propagation/reception_loss.h"
#include "net_models/link_state/link_state_routing.h"
#include "net_models/routing/shortest_path_routing.h"

namespace dvpr {

NetworkStack MakeNetworkStack(const NetworkModelParams& params, int nodes, std::uint64_t run_seed,
                              std::unique_ptr<MobilityModel> mobility) {
  params.Validate(nodes);  // before any model is built from them
  const PropagationParams propagation = PropagationOf(params);
  if (propagation.NeedsPositions() && !mobility) {
    throw std::invalid_argument("model: " + std::string(ToString(params.model)) +
                                " over the radio needs the robots' positions over time (a trajectory)");
  }
  NetworkStack stack;
  stack.mobility = std::move(mobility);
  if (!stack.mobility) stack.mobility = std::make_unique<FixedMobility>(FixedMobility::AtOrigin(nodes));
  stack.propagation = MakePropagation(propagation, *stack.mobility, run_seed);
  stack.access = MakeLinkModel(params, nodes, run_seed);
  std::vector<PairLossOverride> loss_overrides;
  for (const LinkOverrideParams& o : params.links) {
    if (o.loss) loss_overrides.push_back({o.src, o.dst, *o.loss});
  }
  if (params.loss.model != LossModelKind::kNone || !loss_overrides.empty()) {
    stack.loss = std::make_unique<ReceptionLoss>(nodes, params.loss, loss_overrides, run_seed);
  }
  stack.disconnected = params.disconnected;
  stack.CompleteDefaults(nodes);
  switch (params.next_hop) {
    case NextHopKind::kDirect: break;
    case NextHopKind::kShortestPath:
      stack.next_hop = std::make_unique<ShortestPathNextHop>(*stack.propagation, nodes);
      break;
    case NextHopKind::kLinkState: {
      // Its tables fill only from the beacons the robots' routing daemons send
      // (net_models/link_state/daemon/link_state_helper.h): whoever runs the robots starts them.
      auto tables = std::make_unique<LinkStateNextHop>(nodes, params.link_state);
      stack.link_state = tables.get();
      stack.next_hop = std::move(tables);
      break;
    }
  }
  return stack;
}

}  // namespace dvpr
