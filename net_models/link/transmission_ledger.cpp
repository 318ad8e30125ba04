#include "net_models/link/transmission_ledger.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace dvpr {

TransmissionLedger::Id TransmissionLedger::Open(std::span<const NodeId> dsts, std::size_t frames) {
  const Id id = entries_.Acquire();
  Entry& e = entries_[id];
  e.frames_left = frames;
  e.dsts.assign(dsts.begin(), dsts.end());
  e.outcomes.assign(dsts.size(), LinkDelivery{SimTime::Zero(), DropReason::kNone});
  e.slot = 0;
  e.waiting.clear();
  return id;
}

void TransmissionLedger::Reached(Id id, std::size_t i, SimTime at) {
  LinkDelivery& d = entries_[id].outcomes[i];
  d.arrival = std::max(d.arrival, at);
}

void TransmissionLedger::Lost(Id id, std::size_t i, DropReason reason) {
  LinkDelivery& d = entries_[id].outcomes[i];
  if (d.drop == DropReason::kNone) d.drop = reason;
}

void TransmissionLedger::LostEverywhere(Id id, DropReason reason) {
  for (std::size_t i = 0; i < entries_[id].outcomes.size(); ++i) Lost(id, i, reason);
}

void TransmissionLedger::Wait(Id id, std::uint32_t slot, const PendingCopy& copy, std::uint32_t receiver) {
  Entry& e = entries_[id];
  if (e.frames_left == 0) throw std::logic_error("TransmissionLedger: a copy waits for a settled transmission");
  e.slot = slot;
  e.waiting.push_back(AwaitedCopy{copy, receiver});
}

bool TransmissionLedger::Settle(Id id) {
  Entry& e = entries_[id];
  if (e.frames_left == 0) throw std::logic_error("TransmissionLedger: a frame settled twice");
  if (--e.frames_left > 0) return false;
  // Moved out: the owner may send from Complete, and a new transmission grow entries_.
  std::vector<LinkDelivery> outcomes = std::move(e.outcomes);
  std::vector<AwaitedCopy> waiting = std::move(e.waiting);
  const std::uint32_t slot = e.slot;
  owner_.Complete(slot, waiting, outcomes);
  Entry& freed = entries_[id];
  freed.outcomes = std::move(outcomes);  // their capacity serves the next transmission
  waiting.clear();
  freed.waiting = std::move(waiting);
  entries_.Release(id);
  return true;
}

void TransmissionLedger::Refused(Id id, DropReason reason) {
  LostEverywhere(id, reason);
  --entries_[id].frames_left;
}

void TransmissionLedger::HandOver(Id id, std::span<LinkDelivery> out, LinkModel::MediumUse& use) {
  Entry& e = entries_[id];
  if (e.frames_left > 0) {
    for (LinkDelivery& d : out) d.later = true;
    use.pending = id;
    return;
  }
  std::copy(e.outcomes.begin(), e.outcomes.end(), out.begin());
  entries_.Release(id);
}

}  // namespace dvpr
