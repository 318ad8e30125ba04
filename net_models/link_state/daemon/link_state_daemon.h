#pragma once
// A robot's routing daemon for `link_state` routing: what olsrd is to a robot running Linux. It
// sends the robot's beacons through the robot's own transport, like any of its messages, and
// writes what it hears into the robot's routing table (net_models/link_state/link_state_routing.h), which
// the network's routing then follows for every copy the robot sends or relays:
//
// - every `hello`, from virtual time 0, a HELLO (routing_hello_t) on DVPR_HELLO;
// - every `topology`, from 0, a TC (routing_topology_t) with its next sequence number on
//   DVPR_TOPOLOGY; a TC from another robot that is news to the table is sent on once (the flood).
//
// Both channels are link-local (Network::SetLinkLocal): one hop, to the robots that hear the
// sender, never routed. Beacons stop after `until` (the team's last frame): the tables keep what
// they learned for the hold times, so the last answers still find their way.
#include <cstdint>

#include "net_models/link_state/daemon/routing_beacons.h"
#include "agents/messages/transport.h"
#include "net_models/link_state/link_state_routing.h"
#include "sim/sim_time.h"

namespace dvpr {

class LinkStateDaemon {
 public:
  struct Counters {
    std::uint64_t hellos = 0;      // HELLOs sent
    std::uint64_t topologies = 0;  // own TCs sent
    std::uint64_t forwarded = 0;   // others' TCs sent on
  };

  // `routing` must outlive the daemon; the transport is robot `node`'s.
  LinkStateDaemon(Transport& transport, NodeId node, LinkStateNextHop& routing, SimTime until);
  LinkStateDaemon(const LinkStateDaemon&) = delete;
  LinkStateDaemon& operator=(const LinkStateDaemon&) = delete;

  // Subscribes to both channels; the first beacons go out at this virtual time, once every
  // daemon started now has subscribed.
  void Start();
  const Counters& counters() const { return counters_; }

 private:
  void Hello();
  void Topology();

  Transport& transport_;
  NodeId node_;
  LinkStateNextHop& routing_;
  SimTime until_;
  PublishChannel hello_channel_{};
  PublishChannel topology_channel_{};
  Subscription hello_sub_;
  Subscription topology_sub_;
  Counters counters_;
};

}  // namespace dvpr
