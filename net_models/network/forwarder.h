#pragma once
// How the copies of a network's messages travel (network.h), as ns-3's RouteOutput and RouteInput
// with the queues between them: the next hop of each copy (the stack's NextHopRouting), its
// transmission by the medium access (which asks the network's channel who hears it), the copies on
// their way and one arrival event per arrival time (delivering its copies in the order of their
// destinations, as single events scheduled one after another would; it captures only (forwarder,
// slot, range of copies), so it fits the Simulator's inline callback storage), the transmission by a relay of what reached it
// for others (at most kMaxHops transmissions a copy), the copies a contending medium access
// decides later (its TransmissionLedger, lent to the medium at Bind), and with store-and-forward (disconnected_params.h) the copies
// each node holds and its retries.
//
// The network owns the messages (a slab of payload slots, each with a count of the copies that
// still use it) and the counters; the forwarder tells it through ForwarderHost what becomes of a
// copy, and releases a slot's reference only once it no longer reads the slot.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "net_models/core/node_id.h"
#include "net_models/core/units.h"
#include "net_models/link/link_model.h"
#include "net_models/link/pending_copy.h"
#include "net_models/link/transmission_ledger.h"
#include "net_models/network/availability.h"
#include "net_models/network/network_stack.h"
#include "sim/sim_time.h"

namespace dvpr {

class PropagationChannel;
class Simulator;

// What the forwarder asks of the network whose messages it carries (`slot`: a message's payload
// slot).
class ForwarderHost {
 public:
  virtual ~ForwarderHost() = default;
  // The copy has reached its destination now: the host hands it over (or drops it, offline) and
  // releases its reference.
  virtual void Deliver(std::uint32_t slot, const PendingCopy& c) = 0;
  // The copy is lost at a relay or later: the host counts it against its original pair and
  // reports it; the forwarder releases the reference (Release) when it is done with the slot.
  virtual void DropCopy(std::uint32_t slot, const PendingCopy& c, DropReason reason) = 0;
  // One copy fewer uses the slot's message: the last frees the slot.
  virtual void Release(std::uint32_t slot) = 0;
  // Appends the link frames of the slot's message (wire_format.h) to `frames`.
  virtual void AppendFrames(std::uint32_t slot, std::vector<Bytes>& frames) const = 0;
  // What one node's transmission of the slot's message put on the medium when it sent it on (a
  // relay, or its sender after holding it).
  virtual void SentOn(std::uint32_t slot, NodeId sender, const LinkModel::MediumUse& use) = 0;
  // What one copy of the slot's message takes in a holder's buffer (its wire bytes).
  virtual std::int64_t WireBytes(std::uint32_t slot) const = 0;
  // A copy was held for the first time (RouteCounters::held).
  virtual void FirstHeld() = 0;
};

class Forwarder final : private LedgerOwner {
 public:
  // A copy is sent on at most this many times (IP's usual TTL): routing that changes under a
  // copy could pass it back and forth; the next relay drops it (DropReason::kHopLimit).
  static constexpr int kMaxHops = 64;

  // stack (its next hop, medium access and what becomes of a copy without a way), availability
  // and host must outlive the forwarder.
  Forwarder(Simulator& sim, int nodes, NetworkStack& stack, const Availability& availability, ForwarderHost& host);
  Forwarder(const Forwarder&) = delete;
  Forwarder& operator=(const Forwarder&) = delete;

  // Binds the medium access: it settles what it decides later in this forwarder's ledger and
  // asks `channel` who hears whom.
  void Bind(PropagationChannel& channel);
  // With store_and_forward: after `horizon` nothing a held copy waits for changes any more (the
  // robots stand where their trajectories end, the talk windows and beacons are over), so a copy
  // without a way then is not held: one held before is dropped kExpired at its first retry after
  // the horizon that finds no way, one sent after it is dropped kNoRoute at once. No retry is
  // scheduled past the mission's end (hold_time of 100000 h on radios that never meet retried
  // every 100 ms for ever). Default: no horizon.
  void SetHoldHorizon(SimTime horizon) { hold_horizon_ = horizon; }

  // A message from src to dsts now, as `frames`: its transmission (nothing when src is offline),
  // each copy's outcome kept for Take. routed: the next hop of each copy is the routing's;
  // otherwise (a link-local channel) every copy goes straight to its destination.
  LinkModel::MediumUse Transmit(NodeId src, std::span<const NodeId> dsts, std::span<const Bytes> frames,
                                bool routed);
  // A new message in `slot` (the network's payload slot): no copy on its way yet.
  void Open(std::uint32_t slot);
  // After Transmit: copy i of the message in `slot` (from src for dsts[i], numbered `copy`) is
  // taken on its way - held by its sender, awaited from a contending medium, or arriving - and
  // kNone returned, or it is dropped at its sender and the reason returned.
  DropReason Take(std::uint32_t slot, std::size_t i, NodeId src, NodeId dst, std::uint64_t copy);
  // After the Takes: schedules the arrivals of the slot's copies.
  void Launch(std::uint32_t slot) { ScheduleCopies(slot, 0); }

 private:
  bool StoreAndForward() const { return stack_.disconnected.kind == DisconnectedKind::kStoreAndForward; }
  LinkModel::MediumUse TransmitRouted(const LinkTransmission& t, bool routed);
  void ScheduleCopies(std::uint32_t slot, std::uint32_t from);
  // Delivers copies [first, end) of the slot's pending copies (they arrive now), or relays them.
  void DeliverCopies(std::uint32_t slot, std::uint32_t first, std::uint32_t end);
  // since: by copy, when it was first held (store-and-forward), or empty (held from now on).
  void Relay(std::uint32_t slot, std::span<const PendingCopy> copies, std::span<const SimTime> since = {});
  // Keeps a copy whose outcome the medium access decides later (outcomes_[i].later) in the
  // ledger entry of the last transmission: i is its index in the transmission's destinations,
  // copy what it becomes when it arrives.
  void Await(std::uint32_t slot, std::size_t i, const PendingCopy& copy);
  // A contending medium access decided the copies of payload `slot` that waited in one ledger entry.
  void Complete(std::uint32_t slot, std::span<const AwaitedCopy> copies,
                std::span<const LinkDelivery> outcomes) override;
  // Store-and-forward: keeps c at its node until the next retry: kNone, or why it cannot
  // (kBufferFull past hold_bytes; past the hold horizon kExpired for a copy held before, kNoRoute
  // for one never held).
  DropReason Hold(std::uint32_t slot, const PendingCopy& c, SimTime since);
  // The node's retry: expired copies are dropped, the others sent on or held again.
  void Retry(NodeId node);

  Simulator& sim_;
  int nodes_;
  NetworkStack& stack_;
  const Availability& availability_;
  ForwarderHost& host_;

  // By payload slot: its copies on their way, by arrival time, then destination order (the
  // vectors keep their capacity when a slot is reused).
  std::vector<std::vector<PendingCopy>> pending_;

  // The transmissions a contending medium access decides later (csma_link.h, wifi_link.h) and
  // the copies that wait for them, one entry each; lent to the medium at Bind.
  TransmissionLedger ledger_{*this};
  std::uint32_t last_pending_ = LinkModel::MediumUse::kNone;  // the last Transmit's ledger entry

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

  // Scratch reused by every transmission (no allocation once warm).
  std::vector<LinkDelivery> outcomes_;      // by destination of the last Transmit
  std::vector<NodeId> hops_;                // by destination: its next hop
  std::vector<std::uint32_t> receiver_of_;  // by destination: its receiver's index in the transmission
  std::vector<NodeId> receivers_;           // the distinct next hops, when some copy is relayed or has no route
  std::vector<LinkDelivery> routed_outcomes_;  // by receiver
  std::vector<int> hop_slot_;               // by destination: its next hop's index in receivers_, -1: no route
  std::vector<int> receiver_index_;         // by node: its index in receivers_ while they are gathered, else -1
  std::vector<PendingCopy> relay_copies_;   // Relay's: the copies it sends on
  std::vector<SimTime> relay_since_;        // and when each was first held
  std::vector<NodeId> relay_dsts_;          // and their destinations
  std::vector<Bytes> relay_frames_;         // and the message's frames
};

}  // namespace dvpr
