#include "net_models/network.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

#include "sim/simulator.h"

namespace dvpr {

ObserverSubscription::ObserverSubscription(ObserverSubscription&& other) noexcept
    : network_(std::exchange(other.network_, nullptr)), observer_(std::exchange(other.observer_, nullptr)) {}

ObserverSubscription& ObserverSubscription::operator=(ObserverSubscription&& other) noexcept {
  if (this != &other) {
    Reset();
    network_ = std::exchange(other.network_, nullptr);
    observer_ = std::exchange(other.observer_, nullptr);
  }
  return *this;
}

void ObserverSubscription::Reset() {
  if (network_ != nullptr) network_->Unsubscribe(observer_);
  network_ = nullptr;
  observer_ = nullptr;
}

namespace {

NetworkStack WithAccess(std::unique_ptr<LinkModel> link) {
  NetworkStack stack;
  stack.access = std::move(link);
  return stack;
}

// The stack with its defaults filled in, so the channel can be built over its propagation.
NetworkStack Completed(NetworkStack stack, int nodes) {
  if (nodes <= 0) throw std::invalid_argument("robots = " + std::to_string(nodes) + ": need at least one node");
  if (!stack.access) throw std::invalid_argument("Network: no link model");
  stack.CompleteDefaults(nodes);
  return stack;
}

}  // namespace

Network::Network(Simulator& sim, int nodes, std::unique_ptr<LinkModel> link, WireParams wire)
    : Network(sim, nodes, WithAccess(std::move(link)), wire) {}

Network::Network(Simulator& sim, int nodes, NetworkStack stack, WireParams wire)
    : sim_(sim),
      nodes_(nodes),
      stack_(Completed(std::move(stack), nodes)),
      channel_(*stack_.propagation, stack_.loss.get()),
      wire_(wire),
      pairs_(std::max(nodes, 1)) {
  stack_.disconnected.Validate();
  stack_.access->Bind(sim_, *this, channel_);
  wire_.Validate();
  const auto n = static_cast<std::size_t>(nodes);
  endpoints_.assign(n, nullptr);
  offline_from_.assign(n, SimTime::Max());
  offline_until_.assign(n, SimTime::Max());
  senders_.assign(n, NodeCounters{});
  if (StoreAndForward()) {
    held_.resize(n);
    held_bytes_.assign(n, 0);
    retry_scheduled_.assign(n, 0);
  }
}

Network::~Network() = default;

void Network::CheckNode(NodeId node, const char* what) const {
  if (node.value < 0 || node.value >= nodes_) {
    throw std::out_of_range(std::string("Network::") + what + ": node " + std::to_string(node.value) +
                            " outside [0, " + std::to_string(nodes_) + ")");
  }
}

// Ids come from this network's Intern calls; another network's ids would name nothing here.
void Network::CheckNames(ChannelId channel, MessageTypeId type) const {
  if (static_cast<std::size_t>(channel) >= channel_names_.size()) {
    throw std::out_of_range("Network: channel id " + std::to_string(static_cast<std::uint32_t>(channel)) +
                            " was not interned by this network");
  }
  if (static_cast<std::size_t>(type) >= type_names_.size()) {
    throw std::out_of_range("Network: message type id " + std::to_string(static_cast<std::uint32_t>(type)) +
                            " was not interned by this network");
  }
}

ChannelId Network::InternChannel(std::string_view name) {
  if (auto it = channel_ids_.find(name); it != channel_ids_.end()) return ChannelId{it->second};
  const auto id = static_cast<std::uint32_t>(channels_.size());
  channels_.push_back(Channel{std::string(name), {}});
  channel_names_.push_back(channels_.back().name);
  channel_ids_.emplace(std::string(name), id);
  return ChannelId{id};
}

MessageTypeId Network::InternType(std::string_view name) {
  if (auto it = type_ids_.find(name); it != type_ids_.end()) return MessageTypeId{it->second};
  const auto id = static_cast<std::uint32_t>(types_.size());
  types_.emplace_back(name);
  type_names_.push_back(types_.back());
  type_ids_.emplace(std::string(name), id);
  return MessageTypeId{id};
}

void Network::Attach(NodeId node, NetworkEndpoint* endpoint) {
  CheckNode(node, "Attach");
  endpoints_[static_cast<std::size_t>(node.value)] = endpoint;
}

void Network::Join(NodeId node, ChannelId channel) {
  CheckNode(node, "Join");
  auto& members = channels_.at(static_cast<std::size_t>(channel)).members;
  const auto it = std::lower_bound(members.begin(), members.end(), node);
  if (it == members.end() || *it != node) members.insert(it, node);
}

void Network::Leave(NodeId node, ChannelId channel) {
  auto& members = channels_.at(static_cast<std::size_t>(channel)).members;
  const auto it = std::lower_bound(members.begin(), members.end(), node);
  if (it != members.end() && *it == node) members.erase(it);
}

void Network::SetLinkLocal(ChannelId channel) {
  channels_.at(static_cast<std::size_t>(channel)).link_local = true;
}

void Network::SetOffline(NodeId node, SimTime from, SimTime until) {
  CheckNode(node, "SetOffline");
  offline_from_[static_cast<std::size_t>(node.value)] = from;
  offline_until_[static_cast<std::size_t>(node.value)] = until;
}

void Network::SetTalkWindows(NodeId node, std::vector<TalkWindow> windows) {
  CheckNode(node, "SetTalkWindows");
  for (std::size_t i = 0; i < windows.size(); ++i) {
    if (!(windows[i].from < windows[i].until) || (i > 0 && windows[i].from < windows[i - 1].until)) {
      throw std::invalid_argument("Network::SetTalkWindows: node " + std::to_string(node.value) + ": window " +
                                  std::to_string(i) + " is empty or not after the one before it");
    }
  }
  if (talk_windows_.empty()) talk_windows_.resize(static_cast<std::size_t>(nodes_));
  talk_windows_[static_cast<std::size_t>(node.value)] = std::move(windows);
}

bool Network::InTalkWindow(NodeId node, SimTime at) const {
  if (talk_windows_.empty()) return true;
  const std::vector<TalkWindow>& w = talk_windows_[static_cast<std::size_t>(node.value)];
  if (w.empty()) return true;
  // The last window that opens at or before `at`: it is the only one that can hold it.
  const auto it = std::upper_bound(w.begin(), w.end(), at, [](SimTime t, const TalkWindow& x) { return t < x.from; });
  return it != w.begin() && at < std::prev(it)->until;
}

bool Network::DroppedOut(NodeId node, SimTime at) const {
  const auto i = static_cast<std::size_t>(node.value);
  return offline_from_[i] <= at && at < offline_until_[i];
}

bool Network::IsOnline(NodeId node, SimTime at) const { return !DroppedOut(node, at) && InTalkWindow(node, at); }

ObserverSubscription Network::Subscribe(NetworkObserver& observer) {
  observers_.push_back(&observer);
  return ObserverSubscription(this, &observer);
}

void Network::Unsubscribe(NetworkObserver* observer) {
  const auto it = std::find(observers_.begin(), observers_.end(), observer);
  if (it != observers_.end()) observers_.erase(it);
}

std::size_t Network::Send(NodeId src, ChannelId channel, MessageTypeId type, std::vector<std::uint8_t> payload) {
  CheckNode(src, "Send");
  dsts_.clear();
  const Channel& ch = channels_.at(static_cast<std::size_t>(channel));
  for (const NodeId member : ch.members) {
    if (member != src) dsts_.push_back(member);
  }
  if (ch.link_local) channel_.KeepHearers(src, dsts_, sim_.Now());
  Dispatch(src, channel, type, std::move(payload));
  return dsts_.size();
}

void Network::SendTo(NodeId src, std::span<const NodeId> dsts, ChannelId channel, MessageTypeId type,
                     std::vector<std::uint8_t> payload) {
  CheckNode(src, "SendTo");
  dsts_.assign(dsts.begin(), dsts.end());
  for (const NodeId dst : dsts_) {
    CheckNode(dst, "SendTo");
    if (dst == src) throw std::invalid_argument("Network::SendTo: a node does not send to itself");
  }
  Dispatch(src, channel, type, std::move(payload));
}

// Asks the link model about every destination in dsts_ at once (a shared
// medium needs them together), then schedules the deliveries.
void Network::Dispatch(NodeId src, ChannelId channel, MessageTypeId type, std::vector<std::uint8_t>&& payload) {
  CheckNames(channel, type);
  const SimTime now = sim_.Now();
  NodeCounters& sender = senders_[static_cast<std::size_t>(src.value)];
  ++sender.published;
  const std::uint64_t message = messages_++;
  if (dsts_.empty()) return;

  frames_.clear();
  const auto payload_bytes = static_cast<std::int64_t>(payload.size());
  const WireFootprint fp = AppendLinkFrames(
      Bytes(payload_bytes), static_cast<std::int64_t>(ChannelName(channel).size()), wire_, frames_);
  const bool link_local = channels_[static_cast<std::size_t>(channel)].link_local;
  const LinkModel::MediumUse use = TransmitFrom(src, now, sender, /*routed=*/!link_local);
  if (link_local) {
    sender.routing_transmissions += use.transmissions;
    sender.routing_bytes += use.bytes.value();
  }

  const std::uint32_t slot = AllocatePayload(std::move(payload));
  Payload& p = payloads_[slot];
  p.message = message;
  p.src = src;
  p.channel = channel;
  p.type = type;
  p.sent = now;
  p.wire_bytes = fp.wire_bytes.value();
  std::vector<PendingCopy>& pending = pending_[slot];
  pending.clear();
  for (std::size_t i = 0; i < dsts_.size(); ++i) {
    const NodeId dst = dsts_[i];
    const std::uint64_t copy = copies_++;
    LinkCounters& c = pairs_.At(src, dst);
    ++c.messages;
    c.payload_bytes += payload_bytes;
    c.wire_bytes += p.wire_bytes;
    DropReason drop = outcomes_[i].drop;
    if (drop == DropReason::kNoRoute && StoreAndForward()) {
      // The sender keeps it: no transmission yet (0 hops).
      drop = Hold(slot, PendingCopy{dst, src, copy, 0, 0, now}, now);
      if (drop == DropReason::kNone) {
        ++p.refs;
        if (!observers_.empty()) NotifySent(p, dst, copy, drop);
        continue;
      }
    }
    if (!observers_.empty()) NotifySent(p, dst, copy, drop);
    if (outcomes_[i].later) {
      ++p.refs;
      Await(slot, i, PendingCopy{dst, hops_[i], copy, 1, 0, now});
      continue;
    }
    if (drop != DropReason::kNone) {
      ++c.dropped;
      CountDrop(drop);
      continue;
    }
    ++p.refs;
    pending.push_back(PendingCopy{dst, hops_[i], copy, 1, 0, outcomes_[i].arrival});
  }
  if (!observers_.empty()) NotifyMedium(p, src, use);
  if (p.refs == 0) {
    ReleasePayload(slot);
    return;
  }
  ScheduleCopies(slot, 0);
}

// One event per arrival time (usually one for all), for the slot's copies from `from` on, sorted
// by time; stably, so destination order within a time.
void Network::ScheduleCopies(std::uint32_t slot, std::uint32_t from) {
  std::vector<PendingCopy>& pending = pending_[slot];
  const auto by_time = [](const PendingCopy& a, const PendingCopy& b) { return a.arrival < b.arrival; };
  const auto begin = pending.begin() + from;
  if (!std::is_sorted(begin, pending.end(), by_time)) std::stable_sort(begin, pending.end(), by_time);
  const auto count = static_cast<std::uint32_t>(pending.size());
  for (std::uint32_t first = from; first < count;) {
    const SimTime at = pending[first].arrival;
    std::uint32_t end = first + 1;
    while (end < count && pending[end].arrival == at) ++end;
    sim_.ScheduleAt(at, [this, slot, first, end] { DeliverCopies(slot, first, end); });
    first = end;
  }
}

// Copies that reached their destination are delivered, in destination order; those that reached
// a relay are sent on by it, after the deliveries, one transmission per relay.
void Network::DeliverCopies(std::uint32_t slot, std::uint32_t first, std::uint32_t end) {
  std::vector<PendingCopy> relayed;  // allocates only on a network that relays
  for (std::uint32_t k = first; k < end; ++k) {
    // Indexed each time: a delivery may send, and new slots move the vectors (not their contents).
    const PendingCopy c = pending_[slot][k];
    if (c.at == c.dst) {
      Deliver(slot, c);
    } else {
      relayed.push_back(c);
    }
  }
  if (relayed.empty()) return;
  std::stable_sort(relayed.begin(), relayed.end(),
                   [](const PendingCopy& a, const PendingCopy& b) { return a.at < b.at; });
  for (std::size_t i = 0; i < relayed.size();) {
    std::size_t j = i + 1;
    while (j < relayed.size() && relayed[j].at == relayed[i].at) ++j;
    Relay(slot, std::span<const PendingCopy>(relayed).subspan(i, j - i));
    i = j;
  }
}

// The relay `copies.front().at` sends the copies it holds on towards their destinations: its own
// transmission (its queue, its radio, its bytes), routed again from where it is. A copy that
// cannot go on, or has made kMaxHops transmissions already, is dropped here and counted against
// its original pair.
void Network::Relay(std::uint32_t slot, std::span<const PendingCopy> copies, std::span<const SimTime> since) {
  const SimTime now = sim_.Now();
  const NodeId at = copies.front().at;
  Payload& p = payloads_[slot];
  std::uint32_t dropped = 0;
  const auto drop = [&](const PendingCopy& c, DropReason reason) {
    DropCopy(slot, c, reason);
    ++dropped;
  };
  relay_copies_.clear();
  relay_since_.clear();
  dsts_.clear();
  for (std::size_t i = 0; i < copies.size(); ++i) {
    const PendingCopy& c = copies[i];
    if (c.hops >= kMaxHops) {
      drop(c, DropReason::kHopLimit);
      continue;
    }
    relay_copies_.push_back(c);
    relay_since_.push_back(since.empty() ? now : since[i]);
    dsts_.push_back(c.dst);
  }
  if (!dsts_.empty()) {
    frames_.clear();
    AppendLinkFrames(Bytes(static_cast<std::int64_t>(p.bytes.size())),
                     static_cast<std::int64_t>(ChannelName(p.channel).size()), wire_, frames_);
    NodeCounters& relay = senders_[static_cast<std::size_t>(at.value)];
    const LinkModel::MediumUse use = TransmitFrom(at, now, relay, /*routed=*/true);
    if (at != p.src) {  // (a sender that held its own message sends it now: not a relay)
      relay.relay_transmissions += use.transmissions;
      relay.relay_bytes += use.bytes.value();
    }
    // (a retry that finds no route yet sends nothing, and reports nothing)
    if (!observers_.empty() && use.transmissions > 0) NotifyMedium(p, at, use);
  }
  const auto from = static_cast<std::uint32_t>(pending_[slot].size());
  for (std::size_t i = 0; i < relay_copies_.size(); ++i) {
    const PendingCopy& c = relay_copies_[i];
    if (outcomes_[i].later) {
      Await(slot, i, PendingCopy{c.dst, hops_[i], c.copy, std::uint64_t{c.hops} + 1, c.held, now});
    } else if (outcomes_[i].drop == DropReason::kNone) {
      pending_[slot].push_back(
          PendingCopy{c.dst, hops_[i], c.copy, std::uint64_t{c.hops} + 1, c.held, outcomes_[i].arrival});
    } else if (outcomes_[i].drop == DropReason::kNoRoute && StoreAndForward()) {
      const PendingCopy kept{c.dst, at, c.copy, c.hops, c.held, now};
      if (const DropReason why = Hold(slot, kept, relay_since_[i]); why != DropReason::kNone) drop(c, why);
    } else {
      drop(c, outcomes_[i].drop);
    }
  }
  if (pending_[slot].size() > from) ScheduleCopies(slot, from);
  // Last: releasing the last reference frees the slot.
  for (std::uint32_t k = 0; k < dropped; ++k) ReleasePayload(slot);
}

void Network::DropCopy(std::uint32_t slot, const PendingCopy& c, DropReason reason) {
  const Payload& p = payloads_[slot];
  ++pairs_.At(p.src, c.dst).dropped;
  CountDrop(reason);
  if (!observers_.empty()) {
    const MessageCopy m = CopyOf(p, c.dst, c.copy, static_cast<int>(c.hops));
    for (NetworkObserver* o : observers_) o->OnDropped(m, sim_.Now(), reason);
  }
}

// The copy waits for the transmission just handed to the medium access (its ticket is the last).
void Network::Await(std::uint32_t slot, std::size_t i, const PendingCopy& copy) {
  Awaited& a = awaited_[tickets_ - 1];
  a.slot = slot;
  a.copies.push_back(AwaitedCopy{copy, receiver_of_[i]});
}

// The copies that arrive are scheduled as any others; the lost ones are dropped last (releasing
// the last reference frees the slot).
void Network::Complete(std::uint64_t ticket, std::span<const LinkDelivery> outcomes) {
  const auto it = awaited_.find(ticket);
  if (it == awaited_.end()) throw std::logic_error("Network: a medium access completed an unknown transmission");
  const Awaited a = std::move(it->second);
  awaited_.erase(it);
  std::vector<PendingCopy>& pending = pending_[a.slot];
  const auto from = static_cast<std::uint32_t>(pending.size());
  for (const AwaitedCopy& w : a.copies) {
    const LinkDelivery& d = outcomes[w.receiver];
    if (d.later) throw std::logic_error("Network: a medium access completed a copy it left open");
    if (d.drop != DropReason::kNone) continue;
    PendingCopy c = w.copy;
    c.arrival = d.arrival;
    pending.push_back(c);
  }
  if (pending.size() > from) ScheduleCopies(a.slot, from);
  for (const AwaitedCopy& w : a.copies) {
    const DropReason reason = outcomes[w.receiver].drop;
    if (reason == DropReason::kNone) continue;
    DropCopy(a.slot, w.copy, reason);
    ReleasePayload(a.slot);
  }
}

DropReason Network::Hold(std::uint32_t slot, const PendingCopy& c, SimTime since) {
  if (sim_.Now() > hold_horizon_) return c.held ? DropReason::kExpired : DropReason::kNoRoute;
  const auto node = static_cast<std::size_t>(c.at.value);
  const std::int64_t bytes = payloads_[slot].wire_bytes;
  if (held_bytes_[node] + bytes > stack_.disconnected.hold_bytes.value()) return DropReason::kBufferFull;
  held_bytes_[node] += bytes;
  // Counted once per copy: not again when a retry holds it again, nor at the next robot that
  // holds it after a retry sent it on.
  if (!c.held) ++routes_.held;
  held_[node].push_back(HeldCopy{slot, c, since});
  held_[node].back().copy.held = 1;
  if (!retry_scheduled_[node]) {
    // The next whole multiple of retry after now: every holder asks at the same instants.
    const std::int64_t retry = stack_.disconnected.retry.ns();
    const SimTime at = SimTime::Nanos((sim_.Now().ns() / retry + 1) * retry);
    retry_scheduled_[node] = 1;
    sim_.ScheduleAt(at, [this, n = c.at] { Retry(n); });
  }
  return DropReason::kNone;
}

// Copies held hold_time or longer are dropped; the others are offered to the routing again, one
// Relay per message (in the order the node took them), which sends on those that now have a way
// and holds the rest again (since unchanged).
void Network::Retry(NodeId node) {
  const auto n = static_cast<std::size_t>(node.value);
  retry_scheduled_[n] = 0;
  std::vector<HeldCopy> held = std::move(held_[n]);
  held_[n].clear();
  held_bytes_[n] = 0;
  const SimTime now = sim_.Now();
  std::vector<PendingCopy> copies;
  std::vector<SimTime> since;
  for (std::size_t i = 0; i < held.size(); ++i) {
    if (held[i].slot == ~0u) continue;  // taken with an earlier copy of its message
    const std::uint32_t slot = held[i].slot;
    copies.clear();
    since.clear();
    for (std::size_t j = i; j < held.size(); ++j) {
      if (held[j].slot != slot) continue;
      HeldCopy& h = held[j];
      if (now - h.since >= stack_.disconnected.hold_time) {
        Payload& p = payloads_[slot];
        ++pairs_.At(p.src, h.copy.dst).dropped;
        CountDrop(DropReason::kExpired);
        if (!observers_.empty()) {
          const MessageCopy m = CopyOf(p, h.copy.dst, h.copy.copy, static_cast<int>(h.copy.hops));
          for (NetworkObserver* o : observers_) o->OnDropped(m, now, DropReason::kExpired);
        }
        ReleasePayload(slot);  // the message's other copies still hold it
      } else {
        copies.push_back(h.copy);
        since.push_back(h.since);
      }
      h.slot = ~0u;
    }
    if (!copies.empty()) Relay(slot, copies, since);
  }
}

// Fills outcomes_ for dsts_ and frames_, asking the stack's layers in turn: routing (which copies
// have a way), then the medium access (when they arrive), which asks the channel whether they are
// heard. The
// sender counts what its message put on the medium (nothing when it is offline).
LinkModel::MediumUse Network::TransmitFrom(NodeId src, SimTime now, NodeCounters& sender, bool routed) {
  outcomes_.resize(dsts_.size());
  if (!IsOnline(src, now)) {
    // Outside its talk window a store-and-forward sender keeps what it has (routed traffic: a
    // link-local beacon is for the neighbours of the moment, not worth keeping).
    const bool keeps = routed && StoreAndForward() && !InTalkWindow(src, now) && !DroppedOut(src, now);
    std::fill(outcomes_.begin(), outcomes_.end(), LinkDelivery{now, keeps ? DropReason::kNoRoute : DropReason::kOffline});
    return {};
  }
  const LinkModel::MediumUse use = TransmitRouted(LinkTransmission{src, dsts_, now, frames_, tickets_++}, routed);
  sender.transmissions += use.transmissions;
  sender.medium_bytes += use.bytes.value();
  return use;
}

// The routing model names each copy's next hop (hops_); the medium access carries the message to
// the distinct next hops of the copies that have one (a copy without a route never goes on the
// medium: DropReason::kNoRoute), and its channel says which of them hear it. A copy
// whose next hop is not its destination goes on from that relay when it arrives there (Relay).
LinkModel::MediumUse Network::TransmitRouted(const LinkTransmission& t, bool routed) {
  hops_.resize(dsts_.size());
  if (routed) {
    stack_.next_hop->NextHops(t.src, dsts_, t.now, nodes_, hops_);
  } else {
    std::copy(dsts_.begin(), dsts_.end(), hops_.begin());
  }
  const DropReason unheard = routed ? stack_.next_hop->UnheardHop() : DropReason::kOutOfRange;
  receiver_of_.resize(dsts_.size());
  if (std::equal(hops_.begin(), hops_.end(), dsts_.begin())) {  // one hop each: the usual case
    for (std::size_t i = 0; i < dsts_.size(); ++i) receiver_of_[i] = static_cast<std::uint32_t>(i);
    return stack_.access->Transmit(LinkTransmission{t.src, t.dsts, t.now, t.frames, t.ticket, unheard}, outcomes_);
  }
  receivers_.clear();
  hop_slot_.resize(dsts_.size());
  receiver_index_.resize(static_cast<std::size_t>(nodes_), -1);
  for (std::size_t i = 0; i < dsts_.size(); ++i) {
    if (hops_[i] == kNoRoute) {
      hop_slot_[i] = -1;
      continue;
    }
    int& index = receiver_index_[static_cast<std::size_t>(hops_[i].value)];
    if (index < 0) {
      index = static_cast<int>(receivers_.size());
      receivers_.push_back(hops_[i]);
    }
    hop_slot_[i] = index;
  }
  for (const NodeId r : receivers_) receiver_index_[static_cast<std::size_t>(r.value)] = -1;
  routed_outcomes_.resize(receivers_.size());
  LinkModel::MediumUse use;
  if (!receivers_.empty()) {
    use = stack_.access->Transmit(LinkTransmission{t.src, receivers_, t.now, t.frames, t.ticket, unheard},
                                  routed_outcomes_);
  }
  for (std::size_t i = 0; i < dsts_.size(); ++i) {
    outcomes_[i] = hop_slot_[i] < 0 ? LinkDelivery{t.now, DropReason::kNoRoute}
                                    : routed_outcomes_[static_cast<std::size_t>(hop_slot_[i])];
    receiver_of_[i] = static_cast<std::uint32_t>(std::max(hop_slot_[i], 0));
  }
  return use;
}

void Network::NotifyMedium(const Payload& p, NodeId sender, const LinkModel::MediumUse& use) {
  const MediumReport m{.message = p.message,
                       .sent = p.sent,
                       .src = sender,
                       .channel = p.channel,
                       .channel_name = ChannelName(p.channel),
                       .transmissions = use.transmissions,
                       .bytes = use.bytes.value()};
  for (NetworkObserver* o : observers_) o->OnMedium(m);
}

MessageCopy Network::CopyOf(const Payload& p, NodeId dst, std::uint64_t copy, int hops) const {
  return MessageCopy{.message = p.message,
                     .copy = copy,
                     .sent = p.sent,
                     .src = p.src,
                     .dst = dst,
                     .channel = p.channel,
                     .channel_name = ChannelName(p.channel),
                     .type = p.type,
                     .type_name = TypeName(p.type),
                     .payload = p.bytes,
                     .wire_bytes = p.wire_bytes,
                     .hops = hops};
}

void Network::NotifySent(const Payload& p, NodeId dst, std::uint64_t copy, DropReason drop) {
  const MessageCopy m = CopyOf(p, dst, copy, 0);
  for (NetworkObserver* o : observers_) o->OnSent(m);
  if (drop == DropReason::kNone) return;
  for (NetworkObserver* o : observers_) o->OnDropped(m, p.sent, drop);
}

std::uint32_t Network::AllocatePayload(std::vector<std::uint8_t>&& bytes) {
  const std::uint32_t slot = payloads_.Acquire();
  if (slot == pending_.size()) pending_.emplace_back();  // a new slot
  Payload& p = payloads_[slot];
  p.bytes = std::move(bytes);
  p.refs = 0;
  return slot;
}

void Network::ReleasePayload(std::uint32_t slot) {
  Payload& p = payloads_[slot];
  if (p.refs > 0 && --p.refs > 0) return;
  buffers_.Give(std::move(p.bytes));  // kept for the next message, or freed: a slot may stay idle for long
  p.bytes = std::vector<std::uint8_t>();
  payloads_.Release(slot);
}

void Network::Deliver(std::uint32_t slot, const PendingCopy& copy) {
  const SimTime now = sim_.Now();
  const NodeId dst = copy.dst;
  const auto hops = static_cast<int>(copy.hops);
  Payload& p = payloads_[slot];
  LinkCounters& c = pairs_.At(p.src, dst);
  const bool online = IsOnline(dst, now);
  ++(online ? c.delivered : c.dropped);
  if (online) {
    ++routes_.delivered;
    routes_.delivered_hops += copy.hops;
    routes_.max_hops = std::max(routes_.max_hops, hops);
  } else {
    CountDrop(DropReason::kOffline);
  }
  if (!observers_.empty()) {
    const MessageCopy m = CopyOf(p, dst, copy.copy, hops);
    for (NetworkObserver* o : observers_) {
      if (online) {
        o->OnDelivered(m, now);
      } else {
        o->OnDropped(m, now, DropReason::kOffline);
      }
    }
  }
  if (!online) {
    ReleasePayload(slot);
    return;
  }
  // OnReceive may send (and grow payloads_), so copy what it needs first; the
  // byte buffer itself does not move while this delivery holds a reference.
  const ReceivedMessage m{p.src, dst, p.channel, ChannelName(p.channel), p.bytes, p.sent, p.message};
  if (NetworkEndpoint* endpoint = endpoints_[static_cast<std::size_t>(dst.value)]) endpoint->OnReceive(m);
  ReleasePayload(slot);
}

LinkCounters Network::Totals() const {
  LinkCounters t;
  pairs_.ForEach([&t](const LinkCounters& c) {
    t.messages += c.messages;
    t.payload_bytes += c.payload_bytes;
    t.wire_bytes += c.wire_bytes;
    t.delivered += c.delivered;
    t.dropped += c.dropped;
  });
  return t;
}

const LinkCounters& Network::Counters(NodeId src, NodeId dst) const {
  static const LinkCounters kNone;
  const LinkCounters* c = pairs_.Find(src, dst);
  return c != nullptr ? *c : kNone;
}

}  // namespace dvpr
