#pragma once
// Builds the network stack (network_stack.h) of a configured network (link_factory.h's
// NetworkModelParams), as ns-3's helpers install models: the one place above the network that
// names the concrete media, propagations and next hops.
#include <cstdint>
#include <memory>

#include "net_models/helper/link_factory.h"
#include "net_models/mobility/mobility_model.h"
#include "net_models/network/network_stack.h"

namespace dvpr {

// The configured stack for `nodes` nodes: the link model of `params` (MakeLinkModel, seeded by
// run_seed) as the medium access over `mobility` (null: fixed at the origin); the channel's loss
// of params.loss and the links' loss overrides (none when every pair is lossless); the full mesh,
// or for model radio the propagation of params.radio (range or log_distance) over `mobility`,
// which a radio requires (std::invalid_argument without it); the next hop of params.next_hop
// (direct, or shortest_path over that propagation). Where the next models plug in: a medium
// access or routing kind in NetworkModelParams, made here.
NetworkStack MakeNetworkStack(const NetworkModelParams& params, int nodes, std::uint64_t run_seed,
                              std::unique_ptr<MobilityModel> mobility = nullptr);

}  // namespace dvpr
