#pragma once
// ParallelForInOrder: produce(i) for i in [0, count) on the ParallelFor pool, and consume(i,
// value) in index order as soon as value i and all before it are done, so what consume writes
// is the same for any thread count, and memory holds only the values waiting for a slower
// earlier one. consume runs on whichever thread finishes the next value in line, never on two
// threads at once (it needs no locking of its own). The first exception, from produce or
// consume, stops the hand-out and is rethrown after all threads have joined; values not yet
// consumed then are dropped.
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "experiments/domain/parallel/parallel_for.h"

namespace dvpr {

// The values done out of order, and which thread, if any, is consuming.
template <typename T>
class InOrderQueue {
 public:
  explicit InOrderQueue(std::int64_t count) : waiting_(static_cast<std::size_t>(count)) {}

  // Stores value i; then, unless another thread is consuming, consumes every value in line.
  template <typename Consume>
  void Put(std::int64_t i, T&& value, Consume& consume) {
    std::unique_lock lock(mutex_);
    waiting_[static_cast<std::size_t>(i)].emplace(std::move(value));
    if (consuming_ || failed_) return;  // the consuming thread sees value i once it is in line
    consuming_ = true;
    while (next_ < waiting_.size() && waiting_[next_].has_value()) {
      T ready = std::move(*waiting_[next_]);
      waiting_[next_].reset();
      const auto index = static_cast<std::int64_t>(next_++);
      lock.unlock();
      try {
        consume(index, std::move(ready));
      } catch (...) {
        lock.lock();
        consuming_ = false;
        failed_ = true;  // nothing after a failed value is consumed
        throw;
      }
      lock.lock();
    }
    consuming_ = false;
  }

 private:
  std::mutex mutex_;
  std::vector<std::optional<T>> waiting_;
  std::size_t next_ = 0;     // the next index to consume
  bool consuming_ = false;
  bool failed_ = false;
};

template <typename Produce, typename Consume>
void ParallelForInOrder(std::int64_t count, int threads, Produce&& produce, Consume&& consume) {
  using T = std::invoke_result_t<Produce&, std::int64_t>;
  InOrderQueue<T> queue(count);
  ParallelFor(count, threads, [&](std::int64_t i) { queue.Put(i, produce(i), consume); });
}

}  // namespace dvpr
