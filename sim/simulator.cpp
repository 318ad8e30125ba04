#include "sim/simulator.h"

#include <sys/mman.h>

#include <cstdlib>
#include <new>
#include <stdexcept>
#include <string>

namespace dvpr {
namespace {
constexpr std::size_t kChunkBytes = std::size_t{64} << 15;  // sizeof(Slot) << kChunkBits
}  // namespace

Simulator::Simulator() = default;

Simulator::~Simulator() {
  for (std::uint64_t slot = 0; slot < slots_used_; ++slot) SlotAt(slot).~Slot();
  for (Slot* chunk : chunks_) std::free(chunk);
}

void Simulator::AddChunk() {
  static_assert(sizeof(Slot) << kChunkBits == kChunkBytes);
  chunks_.reserve(chunks_.size() + 1);  // so that push_back below cannot throw and leak the chunk
  void* chunk = std::aligned_alloc(kChunkBytes, kChunkBytes);
  if (chunk == nullptr) throw std::bad_alloc();
  // Advice only: without huge pages the chunk works the same, with 512 times the page faults.
  static_cast<void>(madvise(chunk, kChunkBytes, MADV_HUGEPAGE));
  chunks_.push_back(static_cast<Slot*>(chunk));
}

std::pair<std::uint64_t, std::uint64_t> Simulator::AllocateSlot() {
  std::uint64_t slot;
  if (!free_slots_.empty()) {
    slot = free_slots_.back();
    free_slots_.pop_back();
  } else {
    slot = slots_used_++;
    if (slot > kSlotMask) throw std::length_error("Simulator: more than 2^24 events pending at once");
    if ((slot >> kChunkBits) >= chunks_.size()) AddChunk();
    ::new (static_cast<void*>(&SlotAt(slot))) Slot();
  }
  const std::uint64_t key = (next_seq_++ << kSlotBits) | slot;
  SlotAt(slot).key = key;
  ++pending_;
  return {slot, key};
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
  while (!queue_.empty() && !stop_) {
    if (queue_.Top().time > until) break;
    const Entry e = queue_.Pop();
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
