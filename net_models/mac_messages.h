#pragma once
// The messages a contending medium access has on its hands (csma_link.h, wifi_link.h): a message
// is one or more frames, queued at once, each settled on its own (sent, or dropped); the message
// arrives at a destination when its last frame does and all of them reached it, and is reported
// to the network (LinkCompletions) when its last frame is settled.
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "net_models/link_model.h"
#include "net_models/mac_counters.h"
#include "net_models/node_id.h"
#include "net_models/slot_pool.h"
#include "net_models/units.h"
#include "sim/sim_time.h"

namespace dvpr {

// One frame in a station's queue: its bytes and the message (MacMessages id) it belongs to.
struct MacFrame {
  Bytes size;
  std::uint32_t message = 0;
};

class MacMessages {
 public:
  // Transmit's part every contending model shares: opens t's message and puts its frames at the
  // back of the sending station's drop-tail `queue` of `capacity` frames, calling queued() after
  // each (csma starts a ready station's frame at once); a frame that finds the queue full is
  // refused (DropReason::kQueueFull, counted in counters.dropped_queue_full). Returns the
  // message's id; use.bytes grows by the frames queued.
  template <typename Queued>
  std::uint32_t Enqueue(const LinkTransmission& t, std::deque<MacFrame>& queue, std::size_t capacity,
                        MacCounters& counters, LinkModel::MediumUse& use, Queued&& queued) {
    const std::uint32_t id = Open(t.ticket, t.dsts, t.frames.size());
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
  // Transmit's last step: when the queue refused every frame the outcomes are final and written
  // to `out` (the id freed); otherwise every copy is decided later (LinkDelivery::later).
  void HandOver(std::uint32_t id, std::span<LinkDelivery> out);

  // A message of `frames` frames for dsts, sent in transmission `ticket`; returns its id.
  std::uint32_t Open(std::uint64_t ticket, std::span<const NodeId> dsts, std::size_t frames);
  std::span<const NodeId> Destinations(std::uint32_t id) const { return entries_[id].dsts; }
  // A frame reached destination i at `at` (the message's arrival there is its last frame's).
  void Reached(std::uint32_t id, std::size_t i, SimTime at);
  // A frame did not reach destination i: the message is lost there (the first reason stays).
  void Lost(std::uint32_t id, std::size_t i, DropReason reason);
  void LostEverywhere(std::uint32_t id, DropReason reason);
  // One more frame settled. When it was the last, the message is reported to `completions` and
  // its id freed; returns whether it was.
  bool Settle(std::uint32_t id, LinkCompletions& completions);
  std::size_t open() const { return entries_.in_use(); }

 private:
  struct Entry {
    std::uint64_t ticket = 0;
    std::size_t frames_left = 0;
    std::vector<NodeId> dsts;
    std::vector<LinkDelivery> outcomes;
  };
  // Inside Transmit: a frame the queue refused is settled at once, never reported from there.
  void Refused(std::uint32_t id, DropReason reason);

  SlotPool<Entry> entries_;  // by id: a freed id keeps its vectors' capacity for the next message
};

}  // namespace dvpr
