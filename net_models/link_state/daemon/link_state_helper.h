#pragma once
// What a run does to use link_state routing on its robots (ns-3's OlsrHelper in small): the
// beacons' channels become link-local on the network (one hop, never routed), and each robot gets
// a routing daemon on its own transport that writes into the network's link-state tables
// (Network::link_state, set by MakeNetworkStack). The daemons send from Start until `until`.
#include <memory>
#include <span>
#include <vector>

#include "agents/messages/transport.h"
#include "net_models/link_state/daemon/link_state_daemon.h"
#include "net_models/network/network.h"
#include "sim/sim_time.h"

namespace dvpr {

class LinkStateHelper {
 public:
  // Robot r's daemon on transports[r] (transports.size() == network.nodes()); none when the
  // network's next hop is not link_state. The network and the transports outlive the daemons.
  // Throws std::invalid_argument when the transports are not one per node.
  static std::vector<std::unique_ptr<LinkStateDaemon>> Install(Network& network, std::span<Transport* const> transports,
                                                               SimTime until);
};

}  // namespace dvpr
