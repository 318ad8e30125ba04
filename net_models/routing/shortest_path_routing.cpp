#include "net_models/routing/shortest_path_routing.h"

#include <deque>
#include <stdexcept>
#include <string>

namespace dvpr {

ShortestPathNextHop::ShortestPathNextHop(PropagationModel& propagation, int nodes, SimTime refresh)
    : propagation_(propagation), nodes_(nodes), refresh_(refresh) {
  if (nodes <= 0) throw std::invalid_argument("ShortestPathNextHop: need at least one node, got " + std::to_string(nodes));
  if (refresh <= SimTime::Zero()) throw std::invalid_argument("ShortestPathNextHop: the refresh period must be positive");
  first_hop_.resize(static_cast<std::size_t>(nodes));
}

void ShortestPathNextHop::Refresh(SimTime now) {
  const std::int64_t window = now.ns() / refresh_.ns();
  if (window == window_) return;
  window_ = window;
  heard_by_ = HeardBy(propagation_, nodes_, SimTime::Nanos(window * refresh_.ns()));
  for (std::vector<NodeId>& first : first_hop_) first.clear();
}

// Breadth-first from `at`, neighbours in ascending id: each node's first hop is that of the node
// it was reached from (or itself when `at` hears it directly), so ties go to the lowest ids.
const std::vector<NodeId>& ShortestPathNextHop::FirstHops(NodeId at) {
  std::vector<NodeId>& first = first_hop_[static_cast<std::size_t>(at.value)];
  if (!first.empty()) return first;
  first.assign(static_cast<std::size_t>(nodes_), kNoRoute);
  std::deque<NodeId> queue;
  for (const NodeId v : heard_by_[static_cast<std::size_t>(at.value)]) {
    first[static_cast<std::size_t>(v.value)] = v;
    queue.push_back(v);
  }
  while (!queue.empty()) {
    const NodeId u = queue.front();
    queue.pop_front();
    for (const NodeId v : heard_by_[static_cast<std::size_t>(u.value)]) {
      NodeId& hop = first[static_cast<std::size_t>(v.value)];
      if (hop != kNoRoute || v == at) continue;
      hop = first[static_cast<std::size_t>(u.value)];
      queue.push_back(v);
    }
  }
  return first;
}

void ShortestPathNextHop::DoNextHops(NodeId at, std::span<const NodeId> dsts, SimTime now, std::span<NodeId> hops) {
  Refresh(now);
  const std::vector<NodeId>& first = FirstHops(at);
  for (std::size_t i = 0; i < dsts.size(); ++i) hops[i] = first[static_cast<std::size_t>(dsts[i].value)];
}

}  // namespace dvpr
