#pragma once
// A first-in-first-out queue whose slots keep their objects from one element to the next: Push
// hands out the slot with whatever an earlier element left in it, and Pop swaps the front into
// the caller's object, so buffers inside the elements keep their capacity and a queue in its
// steady state allocates nothing. A robot of the 100-robot broadcast queues 99 searches per
// frame; std::deque freed and allocated a 512-byte block each time its elements moved through one.
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace dvpr {

template <class T>
class ReuseQueue {
 public:
  bool empty() const { return count_ == 0; }
  std::size_t size() const { return count_; }

  // The new back element. It holds what its slot last held (or T{}): set every field you read.
  T& Push() {
    if (count_ == slots_.size()) Grow();
    std::size_t tail = head_ + count_;
    if (tail >= slots_.size()) tail -= slots_.size();
    ++count_;
    return slots_[tail];
  }

  // Swaps the front element with `out` and removes it: `out` gets the element, the slot keeps
  // what `out` held for a later Push. The queue must not be empty.
  void PopInto(T& out) {
    using std::swap;
    swap(out, slots_[head_]);
    head_ = head_ + 1 == slots_.size() ? 0 : head_ + 1;
    --count_;
  }

  // Calls f(element) for every element, front to back.
  template <class F>
  void ForEach(F&& f) {
    std::size_t at = head_;
    for (std::size_t i = 0; i < count_; ++i) {
      f(slots_[at]);
      at = at + 1 == slots_.size() ? 0 : at + 1;
    }
  }

  // Removes every element (their slots keep what they hold).
  void clear() { head_ = 0, count_ = 0; }

 private:
  // Twice the slots (at least 8), the elements moved to the front in order.
  void Grow() {
    std::vector<T> grown(std::max<std::size_t>(8, 2 * slots_.size()));
    for (std::size_t i = 0; i < count_; ++i) {
      std::size_t at = head_ + i;
      if (at >= slots_.size()) at -= slots_.size();
      grown[i] = std::move(slots_[at]);
    }
    slots_ = std::move(grown);
    head_ = 0;
  }

  std::vector<T> slots_;
  std::size_t head_ = 0;   // index of the front element
  std::size_t count_ = 0;  // elements queued
};

}  // namespace dvpr
