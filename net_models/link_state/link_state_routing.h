#pragma once
// "link_state": each robot routes on the topology it last learned from beacons, as OLSR does
// (RFC 3626), rather than on the true graph (shortest_path_routing.h). This is the routing
// table each robot keeps - the kernel's, in OLSR's terms; the beacons are real messages that a
// routing daemon on each robot sends through the network like any other (agents/
// link_state_daemon.h) and feeds back here:
//
// - HELLO, every `hello`, to the robots that hear it (one hop): the robots the sender heard
//   within the neighbour hold. A robot whose HELLO listed the receiver is the receiver's
//   symmetric neighbour; the robots it listed are the receiver's two-hop neighbours through it.
// - TC (topology control), every `topology`, flooded to the team: the sender's symmetric
//   neighbours and a sequence number. A robot takes a TC newer than the one it has from that
//   origin, and sends it on once; an older or repeated one is a duplicate (counted).
//
// A robot's graph: itself to its symmetric neighbours, each neighbour to the robots its last
// HELLO listed, each origin to the robots its last TC listed; a HELLO is forgotten one
// neighbour hold after it was heard, a TC one topology hold after (link_state_params.h). Each
// copy goes to the first hop of a shortest path in that graph, ties to the lowest id (as in
// shortest_path), or has no route. A route through a robot that has driven away stays in the
// table until its HELLO is forgotten; the copies sent on it are lost as stale routes
// (DropReason::kStaleRoute).
//
// Simplifications against OLSR, documented in docs/network_model.md: every robot floods (no
// multipoint relays), a TC lists all symmetric neighbours, beacons carry no jitter, and links
// are not tracked one direction at a time beyond the symmetric check.
#include <cstdint>
#include <span>
#include <vector>

#include "net_models/link_state/link_state_params.h"
#include "net_models/routing/next_hop_routing.h"

namespace dvpr {

class LinkStateNextHop final : public NextHopRouting {
 public:
  // What the tables took in, for the run's outputs.
  struct Counters {
    std::uint64_t hellos = 0;       // HELLOs heard
    std::uint64_t topologies = 0;   // TCs heard that were news
    std::uint64_t duplicates = 0;   // TCs heard again (or older than the one kept)
    bool operator==(const Counters&) const = default;
  };

  // Throws std::invalid_argument for no node or invalid params.
  LinkStateNextHop(int nodes, LinkStateParams params);

  const LinkStateParams& params() const { return params_; }
  int nodes() const { return static_cast<int>(tables_.size()); }
  const Counters& counters() const { return counters_; }

  // What `at` advertises at `now`, ascending: in its HELLO, every robot it heard within the
  // neighbour hold; in its TC, its symmetric neighbours.
  std::vector<NodeId> HelloLinks(NodeId at, SimTime now) const;
  std::vector<NodeId> TopologyLinks(NodeId at, SimTime now) const;
  // The sequence number of at's next TC: 1, 2, ... (its own TC, heard back, is a duplicate).
  std::uint32_t NextSequence(NodeId at);

  // `at` heard from's HELLO listing `links` at `now`.
  void OnHello(NodeId at, NodeId from, std::span<const NodeId> links, SimTime now);
  // `at` heard origin's TC number `seq` listing `links` at `now`. True when it was news (the
  // daemon sends it on), false for a duplicate.
  bool OnTopology(NodeId at, NodeId origin, std::uint32_t seq, std::span<const NodeId> links, SimTime now);

 private:
  void DoNextHops(NodeId at, std::span<const NodeId> dsts, SimTime now, std::span<NodeId> hops) override;
  std::string_view DoName() const override { return "link_state"; }
  DropReason DoUnheardHop() const override { return DropReason::kStaleRoute; }

  struct Heard {
    bool known = false;
    SimTime at;                  // when it was heard
    std::uint32_t sequence = 0;  // TCs only
    std::vector<NodeId> links;
  };
  // One robot's knowledge and its routes.
  struct Table {
    std::vector<Heard> hello;      // by neighbour
    std::vector<Heard> topology;   // by origin
    std::uint32_t own_sequence = 0;
    std::vector<NodeId> first_hop;  // by destination, valid until `valid_until` unless dirty
    SimTime valid_until;
    bool dirty = true;
  };

  bool Fresh(const Heard& h, SimTime hold, SimTime now) const { return h.known && now < h.at + hold; }
  bool Symmetric(const Table& t, NodeId at, NodeId v, SimTime now) const;
  void CheckNode(NodeId node) const;  // throws std::out_of_range outside [0, nodes)
  Table& TableOf(NodeId node);
  const Table& TableOf(NodeId node) const;
  // first_hop of `at`'s table for `now`, recomputed when its knowledge changed or expired.
  void Route(NodeId at, Table& t, SimTime now);

  LinkStateParams params_;
  std::vector<Table> tables_;
  Counters counters_;
};

}  // namespace dvpr
