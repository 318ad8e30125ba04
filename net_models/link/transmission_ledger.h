#pragma once
// The one ledger of the transmissions a contending medium access decides later (csma_link.h,
// wifi_link.h): the forwarder owns it and lends it to its medium at Bind. One entry per
// transmission holds both sides of it: the medium's (a message is one or more frames, queued at
// once, each settled on its own - sent or dropped - and it arrives at a destination when its last
// frame does and all of them reached it) and the network's (which payload slot, and which copies
// wait for which destination's outcome). When its last frame is settled the entry goes to its
// owner (LedgerOwner::Complete) and is freed. Ids are reused last freed first.
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "net_models/core/node_id.h"
#include "net_models/core/slot_pool.h"
#include "net_models/core/units.h"
#include "net_models/link/link_model.h"
#include "net_models/link/mac_counters.h"
#include "net_models/link/pending_copy.h"
#include "sim/sim_time.h"

namespace dvpr {

// One frame in a station's queue: its bytes and the transmission (ledger id) it belongs to.
struct MacFrame {
  Bytes size;
  std::uint32_t message = 0;
};

// A copy waiting for a transmission's outcome: what it becomes when it arrives, and the index of
// its receiver among the transmission's destinations.
struct AwaitedCopy {
  PendingCopy copy;
  std::uint32_t receiver = 0;
};

// Who is told when a transmission is decided (the forwarder).
class LedgerOwner {
 public:
  virtual ~LedgerOwner() = default;
  // outcomes[i] for the transmission's destination i (later false); the copies that waited for
  // it, of payload `slot`. Called from the medium's own events, never from inside Transmit.
  virtual void Complete(std::uint32_t slot, std::span<const AwaitedCopy> copies,
                        std::span<const LinkDelivery> outcomes) = 0;
};

class TransmissionLedger {
 public:
  using Id = std::uint32_t;
  explicit TransmissionLedger(LedgerOwner& owner) : owner_(owner) {}
  TransmissionLedger(const TransmissionLedger&) = delete;
  TransmissionLedger& operator=(const TransmissionLedger&) = delete;

  // --- the medium's side ------------------------------------------------------
  // Transmit's part every contending model shares: opens t's entry and puts its frames at the
  // back of the sending station's drop-tail `queue` of `capacity` frames, calling queued() after
  // each (csma starts a ready station's frame at once); a frame that finds the queue full is
  // refused (DropReason::kQueueFull, counted in counters.dropped_queue_full). Returns the entry's
  // id; use.bytes grows by the frames queued.
  template <typename Queued>
  Id Enqueue(const LinkTransmission& t, std::deque<MacFrame>& queue, std::size_t capacity, MacCounters& counters,
             LinkModel::MediumUse& use, Queued&& queued) {
    const Id id = Open(t.dsts, t.frames.size());
    for (const Bytes frame : t.frames) {
      if (queue.size() >= capacity) {
        ++counters.dropped_queue_full;
        Refused(id, DropReason::kQueueFull);
        continue;
      }
      use.bytes += frame;
      queue.push_back(MacFrame{frame, id});
      queued();
    }
    return id;
  }
  // Transmit's last step: when the queue refused every frame the outcomes are final, written to
  // `out` and the entry freed; otherwise every copy is decided later (LinkDelivery::later) and
  // use.pending names the entry, for the network to wait on (Wait).
  void HandOver(Id id, std::span<LinkDelivery> out, LinkModel::MediumUse& use);
  // An entry for a message of `frames` frames for dsts.
  Id Open(std::span<const NodeId> dsts, std::size_t frames);
  std::span<const NodeId> Destinations(Id id) const { return entries_[id].dsts; }
  // A frame reached destination i at `at` (the message's arrival there is its last frame's).
  void Reached(Id id, std::size_t i, SimTime at);
  // A frame did not reach destination i: the message is lost there (the first reason stays).
  void Lost(Id id, std::size_t i, DropReason reason);
  void LostEverywhere(Id id, DropReason reason);
  // One more frame settled. When it was the last, the entry goes to the owner and is freed;
  // returns whether it was.
  bool Settle(Id id);

  // --- the network's side -----------------------------------------------------
  // Copy `copy` of payload `slot` waits for destination `receiver`'s outcome of entry id.
  void Wait(Id id, std::uint32_t slot, const PendingCopy& copy, std::uint32_t receiver);

  std::size_t open() const { return entries_.in_use(); }

 private:
  struct Entry {
    std::size_t frames_left = 0;
    std::vector<NodeId> dsts;
    std::vector<LinkDelivery> outcomes;
    std::uint32_t slot = 0;
    std::vector<AwaitedCopy> waiting;
  };
  // Inside Transmit: a frame the queue refused is settled at once, never reported from there.
  void Refused(Id id, DropReason reason);

  LedgerOwner& owner_;
  SlotPool<Entry> entries_;  // by id: a freed id keeps its vectors' capacity for the next message
};

}  // namespace dvpr
