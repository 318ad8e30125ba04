#include "net_models/link_state/link_state_routing.h"

#include <algorithm>
#include <deque>
#include <stdexcept>
#include <string>

namespace dvpr {

LinkStateNextHop::LinkStateNextHop(int nodes, LinkStateParams params) : params_(params) {
  if (nodes <= 0) throw std::invalid_argument("LinkStateNextHop: need at least one node, got " + std::to_string(nodes));
  params_.Validate();
  tables_.resize(static_cast<std::size_t>(nodes));
  for (Table& t : tables_) {
    t.hello.resize(static_cast<std::size_t>(nodes));
    t.topology.resize(static_cast<std::size_t>(nodes));
  }
}

void LinkStateNextHop::CheckNode(NodeId node) const {
  if (node.value < 0 || node.value >= nodes()) {
    throw std::out_of_range("LinkStateNextHop: node " + std::to_string(node.value) + " outside [0, " +
                            std::to_string(nodes()) + ")");
  }
}

LinkStateNextHop::Table& LinkStateNextHop::TableOf(NodeId node) {
  CheckNode(node);
  return tables_[static_cast<std::size_t>(node.value)];
}

const LinkStateNextHop::Table& LinkStateNextHop::TableOf(NodeId node) const {
  CheckNode(node);
  return tables_[static_cast<std::size_t>(node.value)];
}

// v's last HELLO is fresh and listed `at`: each hears the other.
bool LinkStateNextHop::Symmetric(const Table& t, NodeId at, NodeId v, SimTime now) const {
  const Heard& h = t.hello[static_cast<std::size_t>(v.value)];
  return Fresh(h, params_.NeighborHold(), now) && std::binary_search(h.links.begin(), h.links.end(), at);
}

std::vector<NodeId> LinkStateNextHop::HelloLinks(NodeId at, SimTime now) const {
  const Table& t = TableOf(at);
  std::vector<NodeId> links;
  for (int v = 0; v < nodes(); ++v) {
    if (Fresh(t.hello[static_cast<std::size_t>(v)], params_.NeighborHold(), now)) links.push_back(NodeId(v));
  }
  return links;
}

std::vector<NodeId> LinkStateNextHop::TopologyLinks(NodeId at, SimTime now) const {
  const Table& t = TableOf(at);
  std::vector<NodeId> links;
  for (int v = 0; v < nodes(); ++v) {
    if (Symmetric(t, at, NodeId(v), now)) links.push_back(NodeId(v));
  }
  return links;
}

std::uint32_t LinkStateNextHop::NextSequence(NodeId at) { return ++TableOf(at).own_sequence; }

namespace {

// The advertised links as a sorted set of nodes of [0, nodes), without `self`.
std::vector<NodeId> CleanLinks(std::span<const NodeId> links, int nodes, NodeId self) {
  std::vector<NodeId> out;
  for (const NodeId v : links) {
    if (v.value >= 0 && v.value < nodes && v != self) out.push_back(v);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

void LinkStateNextHop::OnHello(NodeId at, NodeId from, std::span<const NodeId> links, SimTime now) {
  Table& t = TableOf(at);
  CheckNode(from);
  Heard& h = t.hello[static_cast<std::size_t>(from.value)];
  ++counters_.hellos;
  std::vector<NodeId> clean = CleanLinks(links, nodes(), from);
  if (!h.known || clean != h.links || !Fresh(h, params_.NeighborHold(), now)) t.dirty = true;
  h.known = true;
  h.at = now;
  h.links = std::move(clean);
}

bool LinkStateNextHop::OnTopology(NodeId at, NodeId origin, std::uint32_t seq, std::span<const NodeId> links,
                                  SimTime now) {
  Table& t = TableOf(at);
  CheckNode(origin);
  Heard& h = t.topology[static_cast<std::size_t>(origin.value)];
  if (origin == at || (h.known && seq <= h.sequence)) {
    ++counters_.duplicates;
    return false;
  }
  ++counters_.topologies;
  h.known = true;
  h.at = now;
  h.sequence = seq;
  h.links = CleanLinks(links, nodes(), origin);
  t.dirty = true;
  return true;
}

// Breadth-first from `at` over what it knows, neighbours in ascending id. The table stays valid
// until the first fresh entry it used expires (or new knowledge arrives: dirty).
void LinkStateNextHop::Route(NodeId at, Table& t, SimTime now) {
  if (!t.dirty && now < t.valid_until) return;
  const auto n = static_cast<std::size_t>(nodes());
  t.first_hop.assign(n, kNoRoute);
  t.valid_until = SimTime::Max();
  const auto used = [&](const Heard& h, SimTime hold) {
    if (!Fresh(h, hold, now)) return false;
    t.valid_until = std::min(t.valid_until, h.at + hold);
    return true;
  };
  std::deque<NodeId> queue;
  for (std::size_t v = 0; v < n; ++v) {
    const NodeId node(static_cast<int>(v));
    if (node == at || !used(t.hello[v], params_.NeighborHold()) ||
        !std::binary_search(t.hello[v].links.begin(), t.hello[v].links.end(), at)) {
      continue;
    }
    t.first_hop[v] = node;
    queue.push_back(node);
  }
  std::vector<NodeId> next;
  while (!queue.empty()) {
    const NodeId u = queue.front();
    queue.pop_front();
    const auto ui = static_cast<std::size_t>(u.value);
    // u's links: its HELLO (when u is a neighbour) and its TC, merged in ascending id.
    next.clear();
    if (t.first_hop[ui] == u && used(t.hello[ui], params_.NeighborHold())) {
      next.insert(next.end(), t.hello[ui].links.begin(), t.hello[ui].links.end());
    }
    if (used(t.topology[ui], params_.TopologyHold())) {
      next.insert(next.end(), t.topology[ui].links.begin(), t.topology[ui].links.end());
    }
    std::sort(next.begin(), next.end());
    for (const NodeId w : next) {
      NodeId& hop = t.first_hop[static_cast<std::size_t>(w.value)];
      if (hop != kNoRoute || w == at) continue;
      hop = t.first_hop[ui];
      queue.push_back(w);
    }
  }
  t.dirty = false;
}

void LinkStateNextHop::DoNextHops(NodeId at, std::span<const NodeId> dsts, SimTime now, std::span<NodeId> hops) {
  Table& t = TableOf(at);
  Route(at, t, now);
  for (std::size_t i = 0; i < dsts.size(); ++i) hops[i] = t.first_hop[static_cast<std::size_t>(dsts[i].value)];
}

}  // namespace dvpr
