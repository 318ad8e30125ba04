#pragma once
// "shortest_path": ideal routing (ns-3's global routing, Ipv4GlobalRouting): every node knows
// who hears whom and sends each copy to the first hop of a shortest path, in hops, to its
// destination, asked again at every hop; no routing messages, no overhead. Ties go to the
// lowest node id, so runs are deterministic. A destination with no path gets kNoRoute.
//
// Who hears whom is the propagation model's answer (a directed edge u -> v when v hears what u
// sends). The graph is taken once per `refresh` window of virtual time (at the window's start)
// rather than for every copy: robots at 15 m/s move 1.5 m in the default 100 ms, and a team of
// 100 would otherwise cost 10^4 propagation questions per message. A hop chosen on the window's
// graph that no longer hears the sender is lost out of range, as on a real network whose
// routes lag its topology.
#include <cstdint>
#include <vector>

#include "net_models/propagation/propagation_model.h"
#include "net_models/routing/next_hop_routing.h"

namespace dvpr {

class ShortestPathNextHop final : public NextHopRouting {
 public:
  static constexpr SimTime kDefaultRefresh = SimTime::Millis(100);

  // Throws std::invalid_argument for no node or a refresh that is not positive.
  ShortestPathNextHop(PropagationModel& propagation, int nodes, SimTime refresh = kDefaultRefresh);

 private:
  void DoNextHops(NodeId at, std::span<const NodeId> dsts, SimTime now, std::span<NodeId> hops) override;
  std::string_view DoName() const override { return "shortest_path"; }

  // The graph of the window holding `now`, and forgets the first-hop tables of the last one.
  void Refresh(SimTime now);
  // first_hop_[at]: for each destination its first hop from `at` (kNoRoute: none), by BFS.
  const std::vector<NodeId>& FirstHops(NodeId at);

  PropagationModel& propagation_;
  int nodes_;
  SimTime refresh_;
  std::int64_t window_ = -1;
  std::vector<std::vector<NodeId>> heard_by_;     // HeardBy at the window's start
  std::vector<std::vector<NodeId>> first_hop_;    // per source, empty until asked in this window
};

}  // namespace dvpr
