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
// copy gets there is the network stack's (network_stack.h): the routing model
// names its next hop, the medium access (LinkModel) when it arrives, the
// propagation model whether it is heard and what delay the air adds; the
// defaults (direct, full mesh) leave the link model's answer as it is.
//
// Hot path, for ~1 million messages per second: channel and type names are
// interned to small ids once; the payload is moved in and shared by all its
// destinations (one buffer, reference-counted in a slab, no copy per
// destination); the copies of one message that arrive at the same time are
// one event, which delivers them in the order of their destinations (as the
// events of single copies, scheduled one after another, would run: nothing can
// come between them), and it captures only (network, slot, range of copies),
// so it fits the Simulator's inline callback storage.
#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "net_models/link_model.h"
#include "net_models/network_stack.h"
#include "net_models/network_observer.h"
#include "net_models/node_id.h"
#include "net_models/pair_map.h"
#include "net_models/payload_buffers.h"
#include "net_models/propagation_channel.h"
#include "net_models/slot_pool.h"
#include "net_models/units.h"
#include "net_models/wire_format.h"
#include "sim/sim_time.h"

namespace dvpr {

class Simulator;
class Network;

// An interval [from, until) of virtual time in which a node can talk (Network::SetTalkWindows).
struct TalkWindow {
  SimTime from;
  SimTime until;
  bool operator==(const TalkWindow&) const = default;
};

// What a node receives.
struct ReceivedMessage {
  NodeId src;
  NodeId dst;
  ChannelId channel;
  std::string_view channel_name;
  std::span<const std::uint8_t> payload;  // valid during the OnReceive call only
  SimTime sent;
  std::uint64_t message = 0;  // the Send/SendTo call it came from (MessageCopy::message): the same for every copy
};

// A node's receiving side (SimTransport implements it).
class NetworkEndpoint {
 public:
  virtual ~NetworkEndpoint() = default;
  virtual void OnReceive(const ReceivedMessage& message) = 0;
};

// Per directed pair (src -> dst). messages, payload_bytes and wire_bytes count
// every message sent to dst (delivered, dropped, or still in flight);
// wire_bytes is what one copy costs on the wire (wire_format.h) - on a shared
// medium a broadcast is one transmission heard by all, see NodeCounters.
struct LinkCounters {
  std::uint64_t messages = 0;
  std::int64_t payload_bytes = 0;
  std::int64_t wire_bytes = 0;
  std::uint64_t delivered = 0;
  std::uint64_t dropped = 0;
};

// Per sending node: what it published and what it put on the medium, its relaying for others
// (multi-hop routing, network_stack.h) included.
struct NodeCounters {
  std::uint64_t published = 0;       // Send() calls
  std::uint64_t transmissions = 0;   // copies put on a medium (LinkModel::Transmissions)
  std::int64_t medium_bytes = 0;     // frame bytes of those transmissions
  std::uint64_t relay_transmissions = 0;  // of the transmissions: others' messages it sent on
  std::int64_t relay_bytes = 0;           // and their frame bytes
  std::uint64_t routing_transmissions = 0;  // of the transmissions: on link-local channels (a routing
  std::int64_t routing_bytes = 0;           // protocol's beacons, SetLinkLocal) and their frame bytes
};

// What became of all copies, whatever their pair: delivered ones and the hops they took (1 for
// a copy that went straight to its destination), dropped ones by DropReason.
struct RouteCounters {
  std::uint64_t held = 0;            // copies taken into a buffer (store-and-forward), each once: when first held
  std::uint64_t delivered = 0;
  std::uint64_t delivered_hops = 0;  // summed over the delivered copies
  int max_hops = 0;                  // the most any delivered copy took
  std::array<std::uint64_t, kDropReasons> dropped{};  // by static_cast<std::size_t>(DropReason)
  bool operator==(const RouteCounters&) const = default;
};

// Keeps an observer subscribed to a network until destroyed or Reset (RAII).
// Move-only; must not outlive the network.
class [[nodiscard]] ObserverSubscription {
 public:
  ObserverSubscription() = default;
  ObserverSubscription(ObserverSubscription&& other) noexcept;
  ObserverSubscription& operator=(ObserverSubscription&& other) noexcept;
  ~ObserverSubscription() { Reset(); }
  void Reset();

 private:
  friend class Network;
  ObserverSubscription(Network* network, NetworkObserver* observer) : network_(network), observer_(observer) {}
  Network* network_ = nullptr;
  NetworkObserver* observer_ = nullptr;
};

class Network final : private LinkCompletions {
 public:
  // A copy is sent on at most this many times (IP's usual TTL): routing that changes under a
  // copy could pass it back and forth; the next relay drops it (DropReason::kHopLimit).
  static constexpr int kMaxHops = 64;

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
  const WireParams& wire() const { return wire_; }

  // --- names --------------------------------------------------------------
  ChannelId InternChannel(std::string_view name);
  std::string_view ChannelName(ChannelId id) const { return channel_names_[static_cast<std::size_t>(id)]; }
  // The same name as a string that lives as long as the network.
  const std::string& ChannelNameString(ChannelId id) const { return channels_.at(static_cast<std::size_t>(id)).name; }
  MessageTypeId InternType(std::string_view name);
  std::string_view TypeName(MessageTypeId id) const { return type_names_[static_cast<std::size_t>(id)]; }

  // --- membership ---------------------------------------------------------
  // The endpoint that receives node's messages (one per node; null detaches).
  void Attach(NodeId node, NetworkEndpoint* endpoint);
  // Node starts/stops receiving `channel`. Idempotent.
  void Join(NodeId node, ChannelId channel);
  void Leave(NodeId node, ChannelId channel);
  // Messages on `channel` go one hop, to the members that hear the sender when it sends (the
  // propagation model), and are never routed or relayed: a broadcast to the link with a
  // time-to-live of 1, as OLSR's HELLO and TC packets (RFC 3626, section 3.4). A member out of
  // range is not a destination (nothing is dropped for it). Idempotent.
  void SetLinkLocal(ChannelId channel);
  // Node is offline during [from, until): what it sends in that interval and
  // what arrives for it then is dropped (DropReason::kOffline) and counted.
  void SetOffline(NodeId node, SimTime from, SimTime until = SimTime::Max());
  // Node talks only inside these windows [from, until) (Swarm-SLAM's connectivity schedule): outside
  // them it is offline as above, except that with store_and_forward what it sends or holds there
  // waits in its buffer for its next window (its routing finds no way out: kNoRoute) - a robot
  // that cannot talk keeps its data, as the holders of a disconnected radio do. Windows ascending,
  // disjoint, from < until; throws std::invalid_argument otherwise. No windows: always talks.
  void SetTalkWindows(NodeId node, std::vector<TalkWindow> windows);
  bool IsOnline(NodeId node, SimTime at) const;
  // With store_and_forward: after `horizon` nothing a held copy waits for changes any more (the
  // robots stand where their trajectories end, the talk windows and beacons are over), so a copy
  // without a way then is not held: one held before is dropped kExpired at its first retry after
  // the horizon that finds no way, one sent after it is dropped kNoRoute at once. No retry is
  // scheduled past the mission's end (hold_time of 100000 h on radios that never meet retried
  // every 100 ms for ever). Default: no horizon.
  void SetHoldHorizon(SimTime horizon) { hold_horizon_ = horizon; }

  // --- sending ------------------------------------------------------------
  // Publishes payload from src on channel to every node that joined it, except
  // src. Returns the number of destinations.
  std::size_t Send(NodeId src, ChannelId channel, MessageTypeId type, std::vector<std::uint8_t> payload);
  // Sends to the given destinations, regardless of membership (distinct, != src).
  void SendTo(NodeId src, std::span<const NodeId> dsts, ChannelId channel, MessageTypeId type,
              std::vector<std::uint8_t> payload);

  // Where each payload's buffer goes when its last copy is delivered or dropped: a transport
  // encodes into these (Transport::UseBuffers), so sending allocates nothing once warm.
  PayloadBuffers& payload_buffers() { return buffers_; }

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
  ObserverSubscription Subscribe(NetworkObserver& observer);

 private:
  friend class ObserverSubscription;
  struct PendingCopy;

  struct Channel {
    std::string name;
    std::vector<NodeId> members;  // sorted
    bool link_local = false;      // SetLinkLocal
  };
  // 64 bytes (8-byte fields first): at 72, bench_network's KITTI broadcast
  // ran 8% more instructions, most of them in malloc.
  struct Payload {
    std::vector<std::uint8_t> bytes;
    std::uint64_t message = 0;
    SimTime sent;
    std::int64_t wire_bytes = 0;
    std::uint32_t refs = 0;
    NodeId src;
    ChannelId channel{};
    MessageTypeId type{};
  };
  static_assert(sizeof(Payload) <= 64);
  struct StringHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  using NameMap = std::unordered_map<std::string, std::uint32_t, StringHash, std::equal_to<>>;

  void CheckNode(NodeId node, const char* what) const;
  void CheckNames(ChannelId channel, MessageTypeId type) const;
  void Dispatch(NodeId src, ChannelId channel, MessageTypeId type, std::vector<std::uint8_t>&& payload);
  // routed: the routing model names each copy's next hop; otherwise (a link-local channel) every
  // copy goes straight to its destination.
  LinkModel::MediumUse TransmitFrom(NodeId src, SimTime now, NodeCounters& sender, bool routed);
  LinkModel::MediumUse TransmitRouted(const LinkTransmission& t, bool routed);
  // A contending medium access decided the copies of transmission `ticket` it had left open.
  void Complete(std::uint64_t ticket, std::span<const LinkDelivery> outcomes) override;
  // Keeps a copy whose outcome the medium access decides later (outcomes_[i].later): i is its
  // index in dsts_, copy what it becomes when it arrives (its arrival filled in then).
  void Await(std::uint32_t slot, std::size_t i, const PendingCopy& copy);
  // Drops copy c of the slot's message at a relay or later: counted against its original pair and
  // reported; the caller releases its reference.
  void DropCopy(std::uint32_t slot, const PendingCopy& c, DropReason reason);
  // sender: the node whose transmission it was (the message's source, or a relay).
  void NotifyMedium(const Payload& p, NodeId sender, const LinkModel::MediumUse& use);
  std::uint32_t AllocatePayload(std::vector<std::uint8_t>&& bytes);
  void ReleasePayload(std::uint32_t slot);
  void ScheduleCopies(std::uint32_t slot, std::uint32_t from);
  // Delivers copies [first, end) of the slot's pending copies (they arrive now), or relays them.
  void DeliverCopies(std::uint32_t slot, std::uint32_t first, std::uint32_t end);
  // since: by copy, when it was first held (store-and-forward), or empty (held from now on).
  void Relay(std::uint32_t slot, std::span<const PendingCopy> copies, std::span<const SimTime> since = {});
  void Deliver(std::uint32_t slot, const PendingCopy& c);
  MessageCopy CopyOf(const Payload& p, NodeId dst, std::uint64_t copy, int hops) const;
  void NotifySent(const Payload& p, NodeId dst, std::uint64_t copy, DropReason drop);
  void CountDrop(DropReason reason) { ++routes_.dropped[static_cast<std::size_t>(reason)]; }
  // Store-and-forward (disconnected_params.h): keeps copy c at c.at, held since `since`, and
  // schedules that node's retry; false when its buffer has no room.
  // Keeps c at its node until the next retry: kNone, or why it cannot (kBufferFull past hold_bytes;
  // past the hold horizon kExpired for a copy held before, kNoRoute for one never held).
  DropReason Hold(std::uint32_t slot, const PendingCopy& c, SimTime since);
  // The node's retry: expired copies are dropped, the others sent on or held again.
  void Retry(NodeId node);
  bool StoreAndForward() const { return stack_.disconnected.kind == DisconnectedKind::kStoreAndForward; }
  void Unsubscribe(NetworkObserver* observer);

  Simulator& sim_;
  int nodes_;
  NetworkStack stack_;
  PropagationChannel channel_;  // who hears whom (the stack's propagation and loss), lent to the medium at Bind
  WireParams wire_;

  NameMap channel_ids_;
  std::deque<Channel> channels_;  // deque: names handed out as string_view never move
  std::vector<std::string_view> channel_names_;  // by id, into channels_: a cheaper lookup per message
  NameMap type_ids_;
  std::deque<std::string> types_;
  std::vector<std::string_view> type_names_;  // by id, into types_

  std::vector<NetworkEndpoint*> endpoints_;
  std::vector<SimTime> offline_from_;
  std::vector<SimTime> offline_until_;
  std::vector<std::vector<TalkWindow>> talk_windows_;  // by node; empty until the first window is set
  bool InTalkWindow(NodeId node, SimTime at) const;
  bool DroppedOut(NodeId node, SimTime at) const;  // inside [offline_from_, offline_until_) (SetOffline)

  // A copy on its way: where to, the node it arrives at next (dst, or a relay), its number
  // (MessageCopy::copy), the transmissions it has made (the one under way included), whether a
  // robot has held it (store-and-forward: RouteCounters::held counts a copy once, however many
  // robots and retries hold it), when it arrives there. 48 bits number 2.8e14 copies; hops stay
  // <= kMaxHops.
  struct PendingCopy {
    NodeId dst;
    NodeId at;
    std::uint64_t copy : 48;
    std::uint64_t hops : 15;
    std::uint64_t held : 1;
    SimTime arrival;
  };
  static_assert(sizeof(PendingCopy) <= 24);

  SlotPool<Payload> payloads_;
  // By payload slot (grown with payloads_): its copies on their way, by arrival time, then
  // destination order (the vectors keep their capacity when a slot is reused).
  std::vector<std::vector<PendingCopy>> pending_;
  // Copies whose medium access decides later, by the ticket of their transmission (a contending
  // MAC: csma_link.h, wifi_link.h): the slot, and for each copy the index of its receiver among
  // the transmission's destinations.
  struct AwaitedCopy {
    PendingCopy copy;
    std::uint32_t receiver = 0;
  };
  struct Awaited {
    std::uint32_t slot = 0;
    std::vector<AwaitedCopy> copies;
  };
  std::unordered_map<std::uint64_t, Awaited> awaited_;
  std::uint64_t tickets_ = 0;  // transmissions handed to the medium access so far: the next ticket
  std::vector<std::uint32_t> receiver_of_;  // TransmitRouted: by destination, its receiver's index in the transmission
  std::vector<PendingCopy> relay_copies_;  // Relay's scratch: the copies it sends on
  std::vector<SimTime> relay_since_;       // and when each was first held

  // Store-and-forward: by node, the copies it holds (in the order it took them), their bytes,
  // whether its retry is scheduled.
  struct HeldCopy {
    std::uint32_t slot = 0;
    PendingCopy copy;
    SimTime since;
  };
  std::vector<std::vector<HeldCopy>> held_;
  std::vector<std::int64_t> held_bytes_;
  std::vector<char> retry_scheduled_;
  SimTime hold_horizon_ = SimTime::Max();
  PayloadBuffers buffers_;

  PairMap<LinkCounters> pairs_;  // only the pairs that carried a message (1000 robots: 10^6 pairs)
  std::vector<NodeCounters> senders_;
  RouteCounters routes_;
  std::uint64_t messages_ = 0;  // Send/SendTo calls so far: the next MessageCopy::message
  std::uint64_t copies_ = 0;    // copies sent so far: the next MessageCopy::copy
  std::vector<NetworkObserver*> observers_;

  // Scratch buffers reused by every Send (no allocation once warm).
  std::vector<NodeId> dsts_;
  std::vector<Bytes> frames_;
  std::vector<LinkDelivery> outcomes_;
  std::vector<NodeId> hops_;
  std::vector<NodeId> receivers_;           // the distinct next hops, when some copy is relayed or has no route
  std::vector<LinkDelivery> routed_outcomes_;  // by receiver
  std::vector<int> hop_slot_;               // by destination: its next hop's index in receivers_, -1: no route
  std::vector<int> receiver_index_;         // by node: its index in receivers_ while they are gathered, else -1
};

}  // namespace dvpr
