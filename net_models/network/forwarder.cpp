#include "net_models/network/forwarder.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "net_models/propagation/propagation_channel.h"
#include "sim/simulator.h"

namespace dvpr {

Forwarder::Forwarder(Simulator& sim, int nodes, NetworkStack& stack, const Availability& availability,
                     ForwarderHost& host)
    : sim_(sim), nodes_(nodes), stack_(stack), availability_(availability), host_(host) {
  if (StoreAndForward()) {
    const auto n = static_cast<std::size_t>(nodes);
    held_.resize(n);
    held_bytes_.assign(n, 0);
    retry_scheduled_.assign(n, 0);
  }
}

void Forwarder::Bind(PropagationChannel& channel) { stack_.access->Bind(sim_, ledger_, channel); }

// Asks the stack's layers in turn: routing (which copies have a way), then the medium access
// (when they arrive), which asks the channel whether they are heard.
LinkModel::MediumUse Forwarder::Transmit(NodeId src, std::span<const NodeId> dsts, std::span<const Bytes> frames,
                                         bool routed) {
  const SimTime now = sim_.Now();
  outcomes_.resize(dsts.size());
  last_pending_ = LinkModel::MediumUse::kNone;
  if (!availability_.IsOnline(src, now)) {
    // Outside its talk window a store-and-forward sender keeps what it has (routed traffic: a
    // link-local beacon is for the neighbours of the moment, not worth keeping).
    const bool keeps =
        routed && StoreAndForward() && !availability_.InTalkWindow(src, now) && !availability_.DroppedOut(src, now);
    std::fill(outcomes_.begin(), outcomes_.end(), LinkDelivery{now, keeps ? DropReason::kNoRoute : DropReason::kOffline});
    return {};
  }
  const LinkModel::MediumUse use = TransmitRouted(LinkTransmission{src, dsts, now, frames}, routed);
  last_pending_ = use.pending;
  return use;
}

// The routing model names each copy's next hop (hops_); the medium access carries the message to
// the distinct next hops of the copies that have one (a copy without a route never goes on the
// medium: DropReason::kNoRoute), and its channel says which of them hear it. A copy whose next
// hop is not its destination goes on from that relay when it arrives there (Relay).
LinkModel::MediumUse Forwarder::TransmitRouted(const LinkTransmission& t, bool routed) {
  const std::span<const NodeId> dsts = t.dsts;
  hops_.resize(dsts.size());
  if (routed) {
    stack_.next_hop->NextHops(t.src, dsts, t.now, nodes_, hops_);
  } else {
    std::copy(dsts.begin(), dsts.end(), hops_.begin());
  }
  const DropReason unheard = routed ? stack_.next_hop->UnheardHop() : DropReason::kOutOfRange;
  receiver_of_.resize(dsts.size());
  if (std::equal(hops_.begin(), hops_.end(), dsts.begin())) {  // one hop each: the usual case
    for (std::size_t i = 0; i < dsts.size(); ++i) receiver_of_[i] = static_cast<std::uint32_t>(i);
    return stack_.access->Transmit(LinkTransmission{t.src, dsts, t.now, t.frames, unheard}, outcomes_);
  }
  receivers_.clear();
  hop_slot_.resize(dsts.size());
  receiver_index_.resize(static_cast<std::size_t>(nodes_), -1);
  for (std::size_t i = 0; i < dsts.size(); ++i) {
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
    use = stack_.access->Transmit(LinkTransmission{t.src, receivers_, t.now, t.frames, unheard}, routed_outcomes_);
  }
  for (std::size_t i = 0; i < dsts.size(); ++i) {
    outcomes_[i] = hop_slot_[i] < 0 ? LinkDelivery{t.now, DropReason::kNoRoute}
                                    : routed_outcomes_[static_cast<std::size_t>(hop_slot_[i])];
    receiver_of_[i] = static_cast<std::uint32_t>(std::max(hop_slot_[i], 0));
  }
  return use;
}

void Forwarder::Open(std::uint32_t slot) {
  if (slot >= pending_.size()) pending_.resize(static_cast<std::size_t>(slot) + 1);
  pending_[slot].clear();
}

DropReason Forwarder::Take(std::uint32_t slot, std::size_t i, NodeId src, NodeId dst, std::uint64_t copy) {
  const SimTime now = sim_.Now();
  const LinkDelivery& o = outcomes_[i];
  if (o.drop == DropReason::kNoRoute && StoreAndForward()) {
    // The sender keeps it: no transmission yet (0 hops).
    return Hold(slot, PendingCopy{dst, src, copy, 0, 0, now}, now);
  }
  if (o.later) {
    Await(slot, i, PendingCopy{dst, hops_[i], copy, 1, 0, now});
    return DropReason::kNone;
  }
  if (o.drop != DropReason::kNone) return o.drop;
  pending_[slot].push_back(PendingCopy{dst, hops_[i], copy, 1, 0, o.arrival});
  return DropReason::kNone;
}

// One event per arrival time (usually one for all), for the slot's copies from `from` on, sorted
// by time; stably, so destination order within a time.
void Forwarder::ScheduleCopies(std::uint32_t slot, std::uint32_t from) {
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
void Forwarder::DeliverCopies(std::uint32_t slot, std::uint32_t first, std::uint32_t end) {
  std::vector<PendingCopy> relayed;  // allocates only on a network that relays
  for (std::uint32_t k = first; k < end; ++k) {
    // Indexed each time: a delivery may send, and new slots move the vectors (not their contents).
    const PendingCopy c = pending_[slot][k];
    if (c.at == c.dst) {
      host_.Deliver(slot, c);
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
void Forwarder::Relay(std::uint32_t slot, std::span<const PendingCopy> copies, std::span<const SimTime> since) {
  const SimTime now = sim_.Now();
  const NodeId at = copies.front().at;
  std::uint32_t dropped = 0;
  const auto drop = [&](const PendingCopy& c, DropReason reason) {
    host_.DropCopy(slot, c, reason);
    ++dropped;
  };
  relay_copies_.clear();
  relay_since_.clear();
  relay_dsts_.clear();
  for (std::size_t i = 0; i < copies.size(); ++i) {
    const PendingCopy& c = copies[i];
    if (c.hops >= kMaxHops) {
      drop(c, DropReason::kHopLimit);
      continue;
    }
    relay_copies_.push_back(c);
    relay_since_.push_back(since.empty() ? now : since[i]);
    relay_dsts_.push_back(c.dst);
  }
  if (!relay_dsts_.empty()) {
    relay_frames_.clear();
    host_.AppendFrames(slot, relay_frames_);
    const LinkModel::MediumUse use = Transmit(at, relay_dsts_, relay_frames_, /*routed=*/true);
    host_.SentOn(slot, at, use);
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
  for (std::uint32_t k = 0; k < dropped; ++k) host_.Release(slot);
}

// The copy waits for the transmission just handed to the medium access (its entry is the last).
void Forwarder::Await(std::uint32_t slot, std::size_t i, const PendingCopy& copy) {
  if (last_pending_ == LinkModel::MediumUse::kNone) {
    throw std::logic_error("Network: a medium access left a copy open without a ledger entry");
  }
  ledger_.Wait(last_pending_, slot, copy, receiver_of_[i]);
}

// The copies that arrive are scheduled as any others; the lost ones are dropped last (releasing
// the last reference frees the slot).
void Forwarder::Complete(std::uint32_t slot, std::span<const AwaitedCopy> copies,
                         std::span<const LinkDelivery> outcomes) {
  if (copies.empty()) return;  // no copy waited for it
  std::vector<PendingCopy>& pending = pending_[slot];
  const auto from = static_cast<std::uint32_t>(pending.size());
  for (const AwaitedCopy& w : copies) {
    const LinkDelivery& d = outcomes[w.receiver];
    if (d.later) throw std::logic_error("Network: a medium access completed a copy it left open");
    if (d.drop != DropReason::kNone) continue;
    PendingCopy c = w.copy;
    c.arrival = d.arrival;
    pending.push_back(c);
  }
  if (pending.size() > from) ScheduleCopies(slot, from);
  for (const AwaitedCopy& w : copies) {
    const DropReason reason = outcomes[w.receiver].drop;
    if (reason == DropReason::kNone) continue;
    host_.DropCopy(slot, w.copy, reason);
    host_.Release(slot);
  }
}

DropReason Forwarder::Hold(std::uint32_t slot, const PendingCopy& c, SimTime since) {
  if (sim_.Now() > hold_horizon_) return c.held ? DropReason::kExpired : DropReason::kNoRoute;
  const auto node = static_cast<std::size_t>(c.at.value);
  const std::int64_t bytes = host_.WireBytes(slot);
  if (held_bytes_[node] + bytes > stack_.disconnected.hold_bytes.value()) return DropReason::kBufferFull;
  held_bytes_[node] += bytes;
  // Counted once per copy: not again when a retry holds it again, nor at the next robot that
  // holds it after a retry sent it on.
  if (!c.held) host_.FirstHeld();
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
void Forwarder::Retry(NodeId node) {
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
        host_.DropCopy(slot, h.copy, DropReason::kExpired);
        host_.Release(slot);  // the message's other copies still hold it
      } else {
        copies.push_back(h.copy);
        since.push_back(h.since);
      }
      h.slot = ~0u;
    }
    if (!copies.empty()) Relay(slot, copies, since);
  }
}

}  // namespace dvpr
