#include "net_models/link_state/daemon/link_state_daemon.h"

#include <vector>

#include "agents/messages/channels.h"

namespace dvpr {

LinkStateDaemon::LinkStateDaemon(Transport& transport, NodeId node, LinkStateNextHop& routing, SimTime until)
    : transport_(transport), node_(node), routing_(routing), until_(until) {}

void LinkStateDaemon::Start() {
  hello_channel_ = transport_.Intern(channels::kHello);
  topology_channel_ = transport_.Intern(channels::kTopology);
  hello_sub_ = transport_.Subscribe<routing_hello_t>(channels::kHello, [this](const routing_hello_t& m) {
    const std::vector<NodeId> links = LinksOf(m);
    routing_.OnHello(node_, NodeId(m.robot), links, transport_.Now());
  });
  topology_sub_ = transport_.Subscribe<routing_topology_t>(channels::kTopology, [this](const routing_topology_t& m) {
    const std::vector<NodeId> links = LinksOf(m);
    const auto sequence = static_cast<std::uint32_t>(m.sequence);
    if (routing_.OnTopology(node_, NodeId(m.origin), sequence, links, transport_.Now())) {
      transport_.Publish(topology_channel_, m);  // the flood: once per TC, by every robot that took it
      ++counters_.forwarded;
    }
  });
  // The first beacons go out from an event at this same instant, so that every daemon started
  // now has joined the channels before any of them sends.
  transport_.ScheduleAfter(SimTime::Zero(), [this] {
    Hello();
    Topology();
  });
}

void LinkStateDaemon::Hello() {
  const SimTime now = transport_.Now();
  const std::vector<NodeId> links = routing_.HelloLinks(node_, now);
  transport_.Publish(hello_channel_, HelloMessage(node_, links));
  ++counters_.hellos;
  const SimTime period = routing_.params().hello;
  if (now + period <= until_) transport_.ScheduleAfter(period, [this] { Hello(); });
}

void LinkStateDaemon::Topology() {
  const SimTime now = transport_.Now();
  const std::vector<NodeId> links = routing_.TopologyLinks(node_, now);
  transport_.Publish(topology_channel_, TopologyMessage(node_, routing_.NextSequence(node_), links));
  ++counters_.topologies;
  const SimTime period = routing_.params().topology;
  if (now + period <= until_) transport_.ScheduleAfter(period, [this] { Topology(); });
}

}  // namespace dvpr
