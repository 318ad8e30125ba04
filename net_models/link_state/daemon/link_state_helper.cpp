#include "net_models/link_state/daemon/link_state_helper.h"

#include <stdexcept>
#include <string>

#include "agents/messages/channels.h"

namespace dvpr {

std::vector<std::unique_ptr<LinkStateDaemon>> LinkStateHelper::Install(Network& network,
                                                                       std::span<Transport* const> transports,
                                                                       SimTime until) {
  std::vector<std::unique_ptr<LinkStateDaemon>> daemons;
  LinkStateNextHop* tables = network.link_state();
  if (tables == nullptr) return daemons;
  if (transports.size() != static_cast<std::size_t>(network.nodes())) {
    throw std::invalid_argument("LinkStateHelper: " + std::to_string(transports.size()) + " transports for " +
                                std::to_string(network.nodes()) + " nodes");
  }
  network.SetLinkLocal(network.InternChannel(channels::kHello));
  network.SetLinkLocal(network.InternChannel(channels::kTopology));
  daemons.reserve(transports.size());
  for (std::size_t r = 0; r < transports.size(); ++r) {
    daemons.push_back(std::make_unique<LinkStateDaemon>(*transports[r], NodeId(static_cast<int>(r)), *tables, until));
  }
  return daemons;
}

}  // namespace dvpr
