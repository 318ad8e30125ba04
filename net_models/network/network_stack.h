#pragma once
// The network's four concerns (docs/design.md section 4.1), lowest first, one model each and
// each model one file: where the nodes are (MobilityModel), what a transmission reaches
// (PropagationModel), who may send when and when a copy arrives (the medium access: a
// LinkModel), and which way a copy goes (NextHopRouting); the loss on the channel beside them.
// The Network owns the stack and asks its layers in the order routing, medium access (which
// asks the channel: propagation); the agents see none of it. The stack of a configured network
// is network_helper.h's to build.
//
// A layer left empty gets dvpr's default, which together are today's network exactly: nodes
// fixed at the origin, the full mesh, direct one-hop routing. A model of one layer that needs a
// lower one (a range model the positions, the next hop the propagation) is built with a
// reference to it: the stack owns them all and keeps the lower layers alive longer (members are
// destroyed in reverse order).
#include <cstdint>
#include <memory>

#include "net_models/link/link_model.h"
#include "net_models/mobility/mobility_model.h"
#include "net_models/network/disconnected_params.h"
#include "net_models/propagation/propagation_model.h"
#include "net_models/propagation/reception_loss.h"
#include "net_models/routing/next_hop_routing.h"

namespace dvpr {

class LinkStateNextHop;

struct NetworkStack {
  std::unique_ptr<MobilityModel> mobility;        // null: FixedMobility::AtOrigin
  std::unique_ptr<PropagationModel> propagation;  // null: FullMeshPropagation
  std::unique_ptr<LinkModel> access;              // the medium access; required
  std::unique_ptr<NextHopRouting> next_hop;       // null: DirectNextHop
  std::unique_ptr<ReceptionLoss> loss;            // null: no frame is lost on the channel
  // next_hop as the link-state tables its robots' daemons write into, when it is one (set by
  // whoever built it: MakeNetworkStack; net_models/link_state/), else null.
  LinkStateNextHop* link_state = nullptr;
  // What becomes of a copy the routing finds no way for: dropped, or held (store-and-forward).
  DisconnectedParams disconnected;

  // Fills each empty layer but `access` with its default for `nodes` nodes. Throws
  // std::invalid_argument when nodes < 1, access is empty or mobility places a different number
  // of nodes.
  void CompleteDefaults(int nodes);
  // `stack` with its defaults (CompleteDefaults), as a network takes it.
  static NetworkStack Completed(NetworkStack stack, int nodes) {
    stack.CompleteDefaults(nodes);
    return stack;
  }
};

}  // namespace dvpr
