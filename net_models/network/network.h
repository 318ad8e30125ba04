#pragma once
// The simulated network: takes an encoded LCM message from a node, finds its
// destinations, asks the LinkModel when each copy arrives, schedules each
// delivery (or the drop) on the Simulator, and counts everything. What
// happens to each copy is reported to the subscribed observers
// (network_observer.h), which record whatever they need; the network writes
// nothing itself.
//
// Destinations follow LCM's publish/subscribe semantics: a message published on
// a channel goes to every node that has joined that channel, except the sender.
// dvpr's unicast channels are per destination robot (only that robot joins
// DVPR_QUERY_3), and the broadcast channel is joined by all robots. How each
// copy gets there is the forwarder's (forwarder.h) over the network stack
// (network_stack.h): the routing model names its next hop, the medium access
// (LinkModel) when it arrives, the channel (propagation_channel.h) whether it
// is heard and what delay the air adds; the defaults (direct, full mesh) leave
// the link model's answer as it is. The network keeps the names, the members,
// the messages in flight (a payload slab), the counters and the observers.
//
// Hot path, for ~1 million messages per second: channel and type names are
// interned to small ids once; the payload is moved in and shared by all its
// destinations (one buffer, reference-counted in a slab, no copy per
// destination); the copies of one message that arrive at the same time are
// one event (forwarder.h).
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "net_models/core/node_id.h"
#include "net_models/core/pair_map.h"
#include "net_models/core/payload_buffers.h"
#include "net_models/core/units.h"
#include "net_models/core/wire_format.h"
#include "net_models/link/link_model.h"
#include "net_models/network/availability.h"
#include "net_models/network/channel_table.h"
#include "net_models/network/forwarder.h"
#include "net_models/network/network_counters.h"
#include "net_models/network/network_endpoint.h"
#include "net_models/network/network_observer.h"
#include "net_models/network/network_stack.h"
#include "net_models/network/payload_slab.h"
#include "net_models/propagation/propagation_channel.h"
#include "sim/sim_time.h"

namespace dvpr {

class Simulator;

class Network final : private ForwarderHost {
 public:
  // A copy is sent on at most this many times (Forwarder::kMaxHops).
  static constexpr int kMaxHops = Forwarder::kMaxHops;

  // The stack's empty layers get their defaults (NetworkStack::CompleteDefaults).
  Network(Simulator& sim, int nodes, NetworkStack stack, WireParams wire = {});
  // `link` as the medium access, every other layer its default.
  Network(Simulator& sim, int nodes, std::unique_ptr<LinkModel> link, WireParams wire = {});
  ~Network() override;
  Network(const Network&) = delete;
  Network& operator=(const Network&) = delete;

  int nodes() const { return nodes_; }
  Simulator& simulator() { return sim_; }
  const LinkModel& link() const { return *stack_.access; }
  const MobilityModel& mobility() const { return *stack_.mobility; }
  const PropagationModel& propagation() const { return *stack_.propagation; }
  // Reach is not const (a model may keep state); asking it changes nothing the network counts
  // (connectivity.h asks it after a run).
  PropagationModel& propagation() { return *stack_.propagation; }
  const NextHopRouting& next_hop() const { return *stack_.next_hop; }
  // A routing model that learns (link_state) is fed by whoever runs the nodes' daemons.
  NextHopRouting& next_hop() { return *stack_.next_hop; }
  // The link-state tables when the next hop is link_state routing, else null (NetworkStack).
  LinkStateNextHop* link_state() { return stack_.link_state; }
  const WireParams& wire() const { return wire_; }

  // --- names --------------------------------------------------------------
  ChannelId InternChannel(std::string_view name) { return names_.InternChannel(name); }
  std::string_view ChannelName(ChannelId id) const { return names_.ChannelName(id); }
  // The same name as a string that lives as long as the network.
  const std::string& ChannelNameString(ChannelId id) const { return names_.ChannelNameString(id); }
  MessageTypeId InternType(std::string_view name) { return names_.InternType(name); }
  std::string_view TypeName(MessageTypeId id) const { return names_.TypeName(id); }

  // --- membership ---------------------------------------------------------
  // The endpoint that receives node's messages (one per node; null detaches).
  void Attach(NodeId node, NetworkEndpoint* endpoint);
  // Node starts/stops receiving `channel`. Idempotent.
  void Join(NodeId node, ChannelId channel);
  void Leave(NodeId node, ChannelId channel) { names_.Leave(node, channel); }
  // Messages on `channel` go one hop, to the members that hear the sender when it sends (the
  // propagation model), and are never routed or relayed: a broadcast to the link with a
  // time-to-live of 1, as OLSR's HELLO and TC packets (RFC 3626, section 3.4). A member out of
  // range is not a destination (nothing is dropped for it). Idempotent.
  void SetLinkLocal(ChannelId channel) { names_.SetLinkLocal(channel); }
  // Node is offline during [from, until): what it sends in that interval and
  // what arrives for it then is dropped (DropReason::kOffline) and counted.
  void SetOffline(NodeId node, SimTime from, SimTime until = SimTime::Max());
  // Node talks only inside these windows [from, until) (Swarm-SLAM's connectivity schedule): outside
  // them it is offline as above, except that with store_and_forward what it sends or holds there
  // waits in its buffer for its next window (its routing finds no way out: kNoRoute) - a robot
  // that cannot talk keeps its data, as the holders of a disconnected radio do. Windows ascending,
  // disjoint, from < until; throws std::invalid_argument otherwise. No windows: always talks.
  void SetTalkWindows(NodeId node, std::vector<TalkWindow> windows);
  bool IsOnline(NodeId node, SimTime at) const { return availability_.IsOnline(node, at); }
  // With store_and_forward: when nothing a held copy waits for changes any more (Forwarder).
  void SetHoldHorizon(SimTime horizon) { forwarder_.SetHoldHorizon(horizon); }

  // --- sending ------------------------------------------------------------
  // Publishes payload from src on channel to every node that joined it, except
  // src. Returns the number of destinations.
  std::size_t Send(NodeId src, ChannelId channel, MessageTypeId type, std::vector<std::uint8_t> payload);
  // Sends to the given destinations, regardless of membership (distinct, != src).
  void SendTo(NodeId src, std::span<const NodeId> dsts, ChannelId channel, MessageTypeId type,
              std::vector<std::uint8_t> payload);

  // Where each payload's buffer goes when its last copy is delivered or dropped: a transport
  // encodes into these (Transport::UseBuffers), so sending allocates nothing once warm.
  PayloadBuffers& payload_buffers() { return payloads_.buffers(); }

  // --- accounting ---------------------------------------------------------
  // The pair's counters (all zero for a pair that carried nothing).
  const LinkCounters& Counters(NodeId src, NodeId dst) const;
  // Calls f(src, dst, counters) for every pair that carried a message, by source, then destination.
  template <class F>
  void ForEachPair(F&& f) const {
    pairs_.ForEachSorted(f);
  }
  LinkCounters Totals() const;
  const RouteCounters& Routes() const { return routes_; }
  const NodeCounters& Sender(NodeId src) const { return senders_[static_cast<std::size_t>(src.value)]; }

  // --- observing ----------------------------------------------------------
  // From now on `observer` hears every copy sent, delivered and dropped, after
  // the observers subscribed before it, until the subscription ends.
  ObserverSubscription Subscribe(NetworkObserver& observer) { return observers_.Add(observer); }

 private:
  void CheckNode(NodeId node, const char* what) const;
  void Dispatch(NodeId src, ChannelId channel, MessageTypeId type, std::vector<std::uint8_t>&& payload);
  // ForwarderHost.
  void Deliver(std::uint32_t slot, const PendingCopy& c) override;
  void DropCopy(std::uint32_t slot, const PendingCopy& c, DropReason reason) override;
  void Release(std::uint32_t slot) override { payloads_.Release(slot); }
  void AppendFrames(std::uint32_t slot, std::vector<Bytes>& frames) const override;
  void SentOn(std::uint32_t slot, NodeId sender, const LinkModel::MediumUse& use) override;
  std::int64_t WireBytes(std::uint32_t slot) const override { return payloads_[slot].wire_bytes; }
  void FirstHeld() override { ++routes_.held; }
  // sender: the node whose transmission it was (the message's source, or a relay).
  void NotifyMedium(const Payload& p, NodeId sender, const LinkModel::MediumUse& use);
  MessageCopy CopyOf(const Payload& p, NodeId dst, std::uint64_t copy, int hops) const;
  void NotifySent(const Payload& p, NodeId dst, std::uint64_t copy, DropReason drop);
  void CountDrop(DropReason reason) { ++routes_.dropped[static_cast<std::size_t>(reason)]; }

  Simulator& sim_;
  int nodes_;
  NetworkStack stack_;
  PropagationChannel channel_;  // who hears whom (the stack's propagation and loss), lent to the medium at Bind
  WireParams wire_;
  ChannelTable names_;
  std::vector<NetworkEndpoint*> endpoints_;
  Availability availability_;
  Forwarder forwarder_;

  PayloadSlab payloads_;
  PairMap<LinkCounters> pairs_;  // only the pairs that carried a message (1000 robots: 10^6 pairs)
  std::vector<NodeCounters> senders_;
  RouteCounters routes_;
  std::uint64_t messages_ = 0;  // Send/SendTo calls so far: the next MessageCopy::message
  std::uint64_t copies_ = 0;    // copies sent so far: the next MessageCopy::copy
  ObserverList observers_;

  // Scratch buffers reused by every Send (no allocation once warm).
  std::vector<NodeId> dsts_;
  std::vector<Bytes> frames_;
};

}  // namespace dvpr
