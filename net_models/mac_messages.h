#pragma once
// The messages a contending medium access has on its hands (csma_link.h, wifi_link.h): a message
// is one or more frames, queued at once, each settled on its own (sent, or dropped); the message
// arrives at a destination when its last frame does and all of them reached it, and is reported
// to the network (LinkCompletions) when its last frame is settled.
#include <cstdint>
#include <span>
#include <vector>

#include "net_models/link_model.h"
#include "net_models/node_id.h"
#include "sim/sim_time.h"

namespace dvpr {

class MacMessages {
 public:
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
  // Inside Transmit: a frame the queue refused is settled at once, never reported from there.
  void Refused(std::uint32_t id, DropReason reason);
  // Inside Transmit, when every frame settled at once (a full queue refused them all): writes the
  // outcomes to `out` instead and frees the id; false (and nothing written) while frames remain.
  bool SettledAtOnce(std::uint32_t id, std::span<LinkDelivery> out);
  std::size_t open() const { return entries_.size() - free_.size(); }

 private:
  struct Entry {
    std::uint64_t ticket = 0;
    std::size_t frames_left = 0;
    std::vector<NodeId> dsts;
    std::vector<LinkDelivery> outcomes;
  };
  void Free(std::uint32_t id);

  std::vector<Entry> entries_;
  std::vector<std::uint32_t> free_;
};

}  // namespace dvpr
