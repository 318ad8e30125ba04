#pragma once
// link_state routing's beacons (net_models/link_state/link_state_routing.h) as the LCM messages robots
// send (lcmtypes/dvpr/routing_hello_t.lcm, routing_topology_t.lcm): a robot's links as robot
// ids and back. Ids travel as int16_t, as in agent_status_t (a team of up to 32767 robots).
#include <cstdint>
#include <span>
#include <vector>

#include <dvpr/routing_hello_t.hpp>
#include <dvpr/routing_topology_t.hpp>

#include "net_models/core/node_id.h"

namespace dvpr {

routing_hello_t HelloMessage(NodeId robot, std::span<const NodeId> links);
routing_topology_t TopologyMessage(NodeId origin, std::uint32_t sequence, std::span<const NodeId> links);
// The links a beacon lists (as received: the routing tables ignore ids outside the team).
std::vector<NodeId> LinksOf(const routing_hello_t& m);
std::vector<NodeId> LinksOf(const routing_topology_t& m);

}  // namespace dvpr
