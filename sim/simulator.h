#pragma once
// The discrete-event kernel: a clock and a queue of callbacks ordered by
// (time, sequence), so events scheduled for the same time run in the order
// they were scheduled. Passed by reference; never a global.
//
// Layout, for speed (see bench/bench_scheduler.cpp): the queue is a radix
// heap of 16-byte entries (time, key) (sim/radix_event_queue.h, chosen over
// the binary heap of sim/event_heap.h by BM_QueueHold); the callbacks live in a slab of slots
// whose addresses never move, indexed by the low bits of the key. Cancel()
// frees the slot at once and leaves the heap entry behind; the entry is
// skipped when it surfaces (its key no longer matches the slot's).
// With a million pending events the slab is 64 MB read in time order, i.e.
// at random: the queue reports each entry a few pops before it pops, and its
// slot is prefetched then, so the miss overlaps the events before it.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "sim/event_callback.h"
#include "sim/radix_event_queue.h"
#include "sim/sim_time.h"

namespace dvpr {

// Names one scheduled event. Default-constructed ids name nothing.
class EventId {
 public:
  constexpr EventId() = default;
  constexpr bool IsValid() const { return key_ != 0; }
  constexpr auto operator<=>(const EventId&) const = default;

 private:
  friend class Simulator;
  constexpr explicit EventId(std::uint64_t key) : key_(key) {}
  std::uint64_t key_ = 0;  // sequence << kSlotBits | slot
};

class Simulator {
 public:
  Simulator();
  ~Simulator();
  Simulator(const Simulator&) = delete;
  Simulator& operator=(const Simulator&) = delete;

  SimTime Now() const { return now_; }

  // Runs fn at Now() + delay. A negative delay is an error (std::invalid_argument).
  template <typename F>
  EventId Schedule(SimTime delay, F&& fn) {
    if (delay < SimTime::Zero()) ThrowNegativeDelay(delay);
    return ScheduleAt(now_ + delay, std::forward<F>(fn));
  }

  // Runs fn at time `when` >= Now() (std::invalid_argument otherwise).
  template <typename F>
  EventId ScheduleAt(SimTime when, F&& fn) {
    if (when < now_) ThrowPast(when);
    const auto [slot, key] = AllocateSlot();
    SlotAt(slot).fn.Emplace(std::forward<F>(fn));
    Push(when, key);
    return EventId(key);
  }

  // Cancels a pending event; returns false if it already ran, was cancelled,
  // or is running now. A cancelled event never runs.
  bool Cancel(EventId id);

  // Runs events in order until none is left or Stop() is called.
  void Run();
  // Runs every event with time <= until, then advances the clock to `until`
  // (unless stopped earlier), so a later Run resumes from there.
  void Run(SimTime until);
  // Makes the running Run() return after the current event.
  void Stop() { stop_ = true; }

  std::uint64_t EventsExecuted() const { return executed_; }
  std::size_t PendingEvents() const { return pending_; }

 private:
  static constexpr int kSlotBits = 24;  // up to 16.7 million pending events
  static constexpr std::uint64_t kSlotMask = (std::uint64_t{1} << kSlotBits) - 1;
  // Slots per slab chunk: 32768, 2 MiB, one transparent huge page where the kernel has one (a
  // million pending events then fault in 32 pages, not 16 000). Slots are constructed when first
  // handed out, so a small simulation touches little of it.
  static constexpr int kChunkBits = 15;

  // One cache line per pending event.
  struct alignas(64) Slot {
    EventCallback fn;
    std::uint64_t key = 0;  // key of the pending event here; 0 when free or running
  };
  using Chunks = std::vector<Slot*>;  // raw storage: see AddChunk()
  // Prefetches the slot of an event that will run soon (the queue's OnNear).
  struct PrefetchSlot {
    const Chunks* chunks = nullptr;
    void operator()(std::uint64_t key) const {
      const std::uint64_t slot = key & kSlotMask;
      __builtin_prefetch(&(*chunks)[slot >> kChunkBits][slot & ((std::uint64_t{1} << kChunkBits) - 1)]);
    }
  };
  using Queue = BasicRadixEventQueue<PrefetchSlot>;
  using Entry = Queue::Entry;

  Slot& SlotAt(std::uint64_t slot) {
    return chunks_[slot >> kChunkBits][slot & ((std::uint64_t{1} << kChunkBits) - 1)];
  }
  std::pair<std::uint64_t, std::uint64_t> AllocateSlot();
  void AddChunk();
  void Push(SimTime when, std::uint64_t key) { queue_.Push(Entry{when.ns(), key}); }
  void RunUntil(std::int64_t until);
  void Execute(const Entry& e);
  [[noreturn]] static void ThrowNegativeDelay(SimTime delay);
  [[noreturn]] void ThrowPast(SimTime when) const;

  SimTime now_;
  Chunks chunks_;
  Queue queue_{PrefetchSlot{&chunks_}};
  std::vector<std::uint32_t> free_slots_;
  std::uint64_t slots_used_ = 0;  // slots ever handed out (high-water mark)
  std::uint64_t next_seq_ = 1;
  std::uint64_t executed_ = 0;
  std::size_t pending_ = 0;
  bool stop_ = false;
};

}  // namespace dvpr
