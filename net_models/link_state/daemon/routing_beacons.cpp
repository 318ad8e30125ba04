#include "net_models/link_state/daemon/routing_beacons.h"

#include <stdexcept>
#include <string>

namespace dvpr {
namespace {

std::int16_t Id16(NodeId node) {
  if (node.value < 0 || node.value > INT16_MAX) {
    throw std::invalid_argument("routing beacon: robot id " + std::to_string(node.value) + " outside [0, 32767]");
  }
  return static_cast<std::int16_t>(node.value);
}

std::vector<std::int16_t> Ids16(std::span<const NodeId> links) {
  if (links.size() > static_cast<std::size_t>(INT16_MAX)) {
    throw std::invalid_argument("routing beacon: " + std::to_string(links.size()) + " links, at most 32767");
  }
  std::vector<std::int16_t> ids;
  ids.reserve(links.size());
  for (const NodeId v : links) ids.push_back(Id16(v));
  return ids;
}

std::vector<NodeId> Nodes(const std::vector<std::int16_t>& ids) {
  std::vector<NodeId> out;
  out.reserve(ids.size());
  for (const std::int16_t id : ids) out.push_back(NodeId(id));
  return out;
}

}  // namespace

routing_hello_t HelloMessage(NodeId robot, std::span<const NodeId> links) {
  routing_hello_t m;
  m.robot = Id16(robot);
  m.links = Ids16(links);
  m.num_links = static_cast<std::int16_t>(m.links.size());
  return m;
}

routing_topology_t TopologyMessage(NodeId origin, std::uint32_t sequence, std::span<const NodeId> links) {
  routing_topology_t m;
  m.origin = Id16(origin);
  m.sequence = static_cast<std::int32_t>(sequence);
  m.links = Ids16(links);
  m.num_links = static_cast<std::int16_t>(m.links.size());
  return m;
}

std::vector<NodeId> LinksOf(const routing_hello_t& m) { return Nodes(m.links); }
std::vector<NodeId> LinksOf(const routing_topology_t& m) { return Nodes(m.links); }

}  // namespace dvpr
