#pragma once
// The Simulator's priority queue since issue 15: a radix heap (Ahuja, Mehlhorn, Orlin and Tarjan
// 1990) of 16-byte (time, key) entries, popped in (time, key) order. It relies on simulated time
// being monotone: an entry's bucket is the highest bit in which its time differs from `last_`, the
// time of the latest refill, so an entry moves to a lower bucket at most once per bit and a pop
// costs O(1) amortised plus a scan of one bucket, sequential memory instead of a binary heap's
// cache misses (bench/bench_scheduler.cpp: BM_QueueHold; 10^6 pending events is where it matters).
//
// Equal times stay first-in-first-out: the key's high bits are a sequence number, bucket 0 (time
// == last_) is sorted by key when it is refilled, and later pushes at that time carry larger keys,
// so appending keeps it sorted. An entry earlier than last_ (possible only after the Simulator
// peeked at an entry beyond Run(until) and a later ScheduleAt falls before it) goes to a small
// binary heap of its own, which always pops first: all of its times are below last_.
#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <queue>
#include <vector>

namespace dvpr {

class RadixEventQueue {
 public:
  struct Entry {
    std::int64_t time;
    std::uint64_t key;
  };

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }

  void Push(Entry e) {
    ++size_;
    if (e.time < last_) {
      early_.push(e);
      return;
    }
    const int b = BucketOf(e.time);
    buckets_[static_cast<std::size_t>(b)].push_back(e);
    nonempty_ |= std::uint64_t{1} << b;  // bucket 64 never gets a bit: see BucketOf
  }

  // The earliest entry; the queue must not be empty. Not const: it may refill bucket 0.
  const Entry& Top() {
    if (!early_.empty()) return early_.top();
    if (head_ == buckets_[0].size()) Refill();
    return buckets_[0][head_];
  }

  Entry Pop() {
    const Entry e = Top();
    --size_;
    if (!early_.empty()) {
      early_.pop();
    } else if (++head_ == buckets_[0].size()) {
      buckets_[0].clear();
      head_ = 0;
      nonempty_ &= ~std::uint64_t{1};
    }
    return e;
  }

 private:
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const {
      return a.time > b.time || (a.time == b.time && a.key > b.key);
    }
  };

  // 0 when time == last_, else 1 + the index of the highest differing bit (1..64). Times are
  // >= 0 in a Simulator, so bit 63 never differs and bucket 64 stays unused.
  int BucketOf(std::int64_t time) const {
    const auto diff = static_cast<std::uint64_t>(time) ^ static_cast<std::uint64_t>(last_);
    return diff == 0 ? 0 : 64 - std::countl_zero(diff);
  }

  // Bucket 0 is empty: moves the smallest non-empty bucket's entries down around its minimum.
  void Refill() {
    const int b = std::countr_zero(nonempty_ & ~std::uint64_t{1});
    std::vector<Entry>& from = buckets_[static_cast<std::size_t>(b)];
    std::int64_t min_time = from.front().time;
    for (const Entry& e : from) min_time = std::min(min_time, e.time);
    last_ = min_time;
    nonempty_ &= ~(std::uint64_t{1} << b);
    for (const Entry& e : from) {
      const int to = BucketOf(e.time);  // < b: the entries agree with min_time above bit b-1
      buckets_[static_cast<std::size_t>(to)].push_back(e);
      nonempty_ |= std::uint64_t{1} << to;
    }
    from.clear();
    std::vector<Entry>& now = buckets_[0];
    if (now.size() > 1) {
      std::sort(now.begin(), now.end(), [](const Entry& x, const Entry& y) { return x.key < y.key; });
    }
  }

  std::array<std::vector<Entry>, 65> buckets_;
  std::uint64_t nonempty_ = 0;  // bit b set when buckets_[b] may hold entries (b < 64)
  std::size_t head_ = 0;        // next entry of buckets_[0] to pop
  std::size_t size_ = 0;
  std::int64_t last_ = 0;
  std::priority_queue<Entry, std::vector<Entry>, Later> early_;
};

}  // namespace dvpr
