#include "sim/simulator.h"

#include <stdexcept>
#include <string>

namespace dvpr {
namespace {

struct Earlier {
  template <typename E>
  bool operator()(const E& a, const E& b) const {
    return a.time < b.time || (a.time == b.time && a.key < b.key);
  }
};

}  // namespace

Simulator::Simulator() { heap_.reserve(1024); }
Simulator::~Simulator() = default;

std::pair<std::uint64_t, std::uint64_t> Simulator::AllocateSlot() {
  std::uint64_t slot;
  if (!free_slots_.empty()) {
    slot = free_slots_.back();
    free_slots_.pop_back();
  } else {
    slot = slots_used_++;
    if (slot > kSlotMask) throw std::length_error("Simulator: more than 2^24 events pending at once");
    if ((slot >> kChunkBits) >= chunks_.size()) {
      chunks_.push_back(std::make_unique<Slot[]>(std::size_t{1} << kChunkBits));
    }
  }
  const std::uint64_t key = (next_seq_++ << kSlotBits) | slot;
  SlotAt(slot).key = key;
  ++pending_;
  return {slot, key};
}

// Sift-up with a hole: one write per level instead of a swap.
void Simulator::Push(SimTime when, std::uint64_t key) {
  const Entry e{when.ns(), key};
  std::size_t i = heap_.size();
  heap_.push_back(e);
  Entry* h = heap_.data();
  while (i > 0) {
    const std::size_t parent = (i - 1) / 2;
    if (!Earlier{}(e, h[parent])) break;
    h[i] = h[parent];
    i = parent;
  }
  h[i] = e;
}

// Moves the last entry into the root's hole, sifting it down.
Simulator::Entry Simulator::PopTop() {
  Entry* h = heap_.data();
  const Entry top = h[0];
  const Entry last = h[heap_.size() - 1];
  heap_.pop_back();
  const std::size_t n = heap_.size();
  if (n == 0) return top;
  std::size_t i = 0;
  for (;;) {
    std::size_t child = 2 * i + 1;
    if (child >= n) break;
    if (child + 1 < n && Earlier{}(h[child + 1], h[child])) ++child;
    if (!Earlier{}(h[child], last)) break;
    h[i] = h[child];
    i = child;
  }
  h[i] = last;
  return top;
}

bool Simulator::Cancel(EventId id) {
  if (!id.IsValid()) return false;
  const std::uint64_t slot = id.key_ & kSlotMask;
  if (slot >= slots_used_) return false;
  Slot& s = SlotAt(slot);
  if (s.key != id.key_) return false;
  s.key = 0;
  s.fn.Reset();
  free_slots_.push_back(static_cast<std::uint32_t>(slot));
  --pending_;
  return true;
}

void Simulator::Execute(const Entry& e) {
  const std::uint64_t slot = e.key & kSlotMask;
  Slot& s = SlotAt(slot);
  now_ = SimTime::Nanos(e.time);
  s.key = 0;  // running: Cancel() on it now returns false
  --pending_;
  ++executed_;
  try {
    s.fn();
  } catch (...) {
    s.fn.Reset();
    free_slots_.push_back(static_cast<std::uint32_t>(slot));
    throw;
  }
  s.fn.Reset();
  free_slots_.push_back(static_cast<std::uint32_t>(slot));
}

void Simulator::RunUntil(std::int64_t until) {
  stop_ = false;
  while (!heap_.empty() && !stop_) {
    if (heap_.front().time > until) break;
    const Entry e = PopTop();
    if (SlotAt(e.key & kSlotMask).key != e.key) continue;  // cancelled
    Execute(e);
  }
}

void Simulator::Run() { RunUntil(SimTime::Max().ns()); }

void Simulator::Run(SimTime until) {
  RunUntil(until.ns());
  if (!stop_ && now_ < until) now_ = until;
}

void Simulator::ThrowNegativeDelay(SimTime delay) {
  throw std::invalid_argument("Simulator::Schedule: negative delay " + std::to_string(delay.ns()) + "ns");
}

void Simulator::ThrowPast(SimTime when) const {
  throw std::invalid_argument("Simulator::ScheduleAt: time " + std::to_string(when.ns()) +
                              "ns is before now (" + std::to_string(now_.ns()) + "ns)");
}

}  // namespace dvpr
