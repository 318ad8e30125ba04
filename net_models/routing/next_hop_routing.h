#pragma once
// Which way a message goes (docs/design.md section 4.1, "routing"): the neighbour a node hands
// its copy for a destination to, at a virtual time. This is the network's routing, below the
// agents: which robot a query is for is the agents' routing strategy (agents/); how the copy
// gets there is this model's, and the agents never see it (as IP's routing is invisible to an
// application). ns-3's Ipv4RoutingProtocol::RouteOutput, one question per copy.
//
// A model that needs to know who hears whom is built over the PropagationModel; one whose
// beacons are real messages would send them through the Network like any node.
//
// NextHops is the public, non-virtual entry point (NVI): it presets every hop to its
// destination (one hop, the full mesh's answer), asks the model, then checks what it answered.
#include <span>
#include <string_view>

#include "net_models/core/node_id.h"
#include "net_models/core/transmission.h"
#include "sim/sim_time.h"

namespace dvpr {

// The routing models a config names (network.routing; MakeNetworkStack builds them):
// "direct" (direct_routing.h) | "shortest_path" (shortest_path_routing.h) | "link_state"
// (link_state_routing.h). Parse throws std::invalid_argument "unknown value '<name>' (expected
// one of: direct, shortest_path, link_state)".
enum class NextHopKind { kDirect, kShortestPath, kLinkState };
NextHopKind ParseNextHopKind(std::string_view name);
std::string_view ToString(NextHopKind kind);

// The answer for a destination that cannot be reached now: the copy is dropped
// (DropReason::kNoRoute). Store-and-forward is a model that answers a hop instead.
inline constexpr NodeId kNoRoute{-1};

class NextHopRouting {
 public:
  virtual ~NextHopRouting() = default;

  // Fills hops[i] for dsts[i] (hops.size() == dsts.size(); dsts distinct nodes of [0, nodes),
  // none equal to `at`): dsts[i] itself (one hop), another node (it relays), or kNoRoute.
  // Throws std::logic_error when the model answers `at` itself or a node outside [0, nodes).
  void NextHops(NodeId at, std::span<const NodeId> dsts, SimTime now, int nodes, std::span<NodeId> hops);
  // "direct", "shortest_path", ...
  std::string_view Name() const { return DoName(); }
  // Why a copy is lost when the hop this model named does not hear it: out of range for a model
  // that knows the graph (direct's one hop, shortest_path's graph of the last 100 ms), a stale
  // route for one that routes on what it learned (link_state).
  DropReason UnheardHop() const { return DoUnheardHop(); }

 private:
  // hops[i] arrives preset to dsts[i].
  virtual void DoNextHops(NodeId at, std::span<const NodeId> dsts, SimTime now, std::span<NodeId> hops) = 0;
  virtual std::string_view DoName() const = 0;
  virtual DropReason DoUnheardHop() const { return DropReason::kOutOfRange; }
};

}  // namespace dvpr
