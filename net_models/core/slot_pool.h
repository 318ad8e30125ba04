#pragma once
// Numbered slots of T, reused last-freed-first: the network's payloads (network.h), a contending
// MAC's open transmissions (transmission_ledger.h) and wifi's transmissions on the air (wifi_link.h) are each
// known by a small slot number that an event captures instead of a pointer.
//
// A released slot's T is left as it is: the next Acquire hands it back with its state (a
// vector's capacity, and its contents too), so the caller sets every field it uses and clears
// what it must. Reuse is LIFO, so a run in its steady state keeps reusing the same few slots
// (warm in cache, their capacity already grown) and makes no new ones.
//
// The slots live in one std::vector: an Acquire that makes a new slot may move every T, so a
// reference to a slot does not survive it (index again), while the heap buffers a T owns (its
// vectors' contents) move with it and stay where they are.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace dvpr {

template <typename T>
class SlotPool {
 public:
  // The slot released last, its T as it was left; else a new default T at the end (slot size()).
  [[nodiscard]] std::uint32_t Acquire() {
    if (!free_.empty()) {
      const std::uint32_t slot = free_.back();
      free_.pop_back();
      return slot;
    }
    const auto slot = static_cast<std::uint32_t>(slots_.size());
    slots_.emplace_back();
    return slot;
  }
  // Gives back a slot in use (each acquired slot once; not checked); its T is kept for reuse.
  void Release(std::uint32_t slot) { free_.push_back(slot); }

  T& operator[](std::uint32_t slot) { return slots_[slot]; }
  const T& operator[](std::uint32_t slot) const { return slots_[slot]; }
  // Slots made so far (in use or free): the slots are 0 .. size() - 1.
  std::size_t size() const { return slots_.size(); }
  // Slots acquired and not released.
  std::size_t in_use() const { return slots_.size() - free_.size(); }

 private:
  std::vector<T> slots_;
  std::vector<std::uint32_t> free_;  // a stack: the back is the next Acquire
};

}  // namespace dvpr
