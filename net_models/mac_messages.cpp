#include "net_models/mac_messages.h"

#include <algorithm>
#include <stdexcept>

namespace dvpr {

std::uint32_t MacMessages::Open(std::uint64_t ticket, std::span<const NodeId> dsts, std::size_t frames) {
  const std::uint32_t id = entries_.Acquire();
  Entry& e = entries_[id];
  e.ticket = ticket;
  e.frames_left = frames;
  e.dsts.assign(dsts.begin(), dsts.end());
  e.outcomes.assign(dsts.size(), LinkDelivery{SimTime::Zero(), DropReason::kNone});
  return id;
}

void MacMessages::Reached(std::uint32_t id, std::size_t i, SimTime at) {
  LinkDelivery& d = entries_[id].outcomes[i];
  d.arrival = std::max(d.arrival, at);
}

void MacMessages::Lost(std::uint32_t id, std::size_t i, DropReason reason) {
  LinkDelivery& d = entries_[id].outcomes[i];
  if (d.drop == DropReason::kNone) d.drop = reason;
}

void MacMessages::LostEverywhere(std::uint32_t id, DropReason reason) {
  for (std::size_t i = 0; i < entries_[id].outcomes.size(); ++i) Lost(id, i, reason);
}

bool MacMessages::Settle(std::uint32_t id, LinkCompletions& completions) {
  Entry& e = entries_[id];
  if (e.frames_left == 0) throw std::logic_error("MacMessages: a frame settled twice");
  if (--e.frames_left > 0) return false;
  // Moved out: the network may send from Complete, and a new message grow entries_.
  std::vector<LinkDelivery> outcomes = std::move(e.outcomes);
  completions.Complete(e.ticket, outcomes);
  entries_[id].outcomes = std::move(outcomes);  // its capacity serves the next message
  entries_.Release(id);
  return true;
}

void MacMessages::Refused(std::uint32_t id, DropReason reason) {
  LostEverywhere(id, reason);
  --entries_[id].frames_left;
}

void MacMessages::HandOver(std::uint32_t id, std::span<LinkDelivery> out) {
  Entry& e = entries_[id];
  if (e.frames_left > 0) {
    for (LinkDelivery& d : out) d.later = true;
    return;
  }
  std::copy(e.outcomes.begin(), e.outcomes.end(), out.begin());
  entries_.Release(id);
}

}  // namespace dvpr
