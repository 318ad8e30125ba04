#pragma once
// The Simulator's priority queue (issue 15): a radix heap with 256-way digits (a hierarchical
// timing wheel with exact times) of 16-byte (time, key) entries, popped in (time, key) order.
// It relies on simulated time being monotone: entries never come before the block being drained.
//
// Times are split into 8-bit digits. The queue drains one block of 256 ns at a time
// ([base_, base_ + 256)): the entries of that block sit in `run_`, sorted by (time, key), and in
// `near_`, a small binary heap for those pushed into it (or before it: see below) after it was
// sorted; a pop takes the smaller head of the two. A later entry sits in the wheel, at the level
// of the highest digit in which its time differs from base_, in the bucket of its own digit there.
// When the block is drained, the first non-empty bucket of the lowest non-empty level is spread
// over the levels below it (relative to the start of the bucket's range, the new base_), until a
// level-1 bucket, one whole block, comes down: it is counting-sorted on its last digit into run_.
// An entry thus moves once per digit (twice for delays up to 2^24 ns), always by a sequential
// append, where a binary heap takes a cache miss per level and the binary radix heap (this file
// before) moved it once per bit (bench/bench_scheduler.cpp: BM_QueueHold, BM_HoldModel).
//
// Equal times stay first-in-first-out without comparing keys in the wheel: keys grow with every
// push, a bucket is only ever spread into levels that are empty at that moment and spreading keeps
// the order, so every bucket is sorted by key, and the counting sort is stable. An entry earlier
// than base_ (possible only after the Simulator peeked at an entry beyond Run(until) and a later
// ScheduleAt falls before it) goes to near_ too, whose order is by (time, key) in full.
//
// `OnNear` is told the key of an entry a few pops before it pops (from run_, where the misses
// are); the Simulator uses it to prefetch the event's callback.
#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <queue>
#include <utility>
#include <vector>

namespace dvpr {

struct IgnoreNearEntries {
  void operator()(std::uint64_t /*key*/) const {}
};

template <typename OnNear = IgnoreNearEntries>
class BasicRadixEventQueue {
 public:
  struct Entry {
    std::int64_t time;
    std::uint64_t key;
  };

  BasicRadixEventQueue() = default;
  explicit BasicRadixEventQueue(OnNear on_near) : on_near_(on_near) {}

  bool empty() const { return size_ == 0; }
  std::size_t size() const { return size_; }

  // Keys must grow from push to push (the Simulator's sequence numbers do); times are >= 0.
  void Push(Entry e) {
    ++size_;
    if (e.time < base_ + static_cast<std::int64_t>(kDigits)) {
      near_.push(e);
    } else {
      Append(e);
    }
  }

  // The earliest entry; the queue must not be empty. Not const: it may bring the next block down.
  const Entry& Top() {
    if (head_ == run_.size() && near_.empty()) Advance();
    return FromRun() ? run_[head_] : near_.top();
  }

  Entry Pop() {
    const Entry e = Top();
    --size_;
    if (FromRun()) {
      if (head_ + kLookAhead < run_.size()) on_near_(run_[head_ + kLookAhead].key);
      ++head_;
    } else {
      near_.pop();
    }
    return e;
  }

 private:
  static constexpr int kDigitBits = 8;
  static constexpr unsigned kDigits = 1u << kDigitBits;
  static constexpr unsigned kDigitMask = kDigits - 1;
  static constexpr int kLevels = (63 + kDigitBits - 1) / kDigitBits;  // 0..7; 1..7 are used
  static constexpr int kWords = kDigits / 64;
  static constexpr std::size_t kLookAhead = 8;    // pops between OnNear and the pop
  static constexpr std::size_t kSmallSort = 24;   // below this, insertion sort beats counting

  // A bucket is a list of fixed-size pages from the queue's own pool, not a std::vector: a
  // bucket fills up once per lap of its level, and vectors would keep every lap's capacity
  // (hundreds of MB after a long run at 10^6 pending) and copy when they grow.
  struct Page {
    static constexpr std::size_t kEntries = 127;  // 2 KiB with the header
    Page* next = nullptr;
    std::size_t count = 0;
    Entry entries[kEntries];
  };
  struct Bucket {
    Page* head = nullptr;
    Page* tail = nullptr;
  };
  struct Level {
    std::array<Bucket, kDigits> buckets;
    std::array<std::uint64_t, kWords> nonempty{};  // bit d set when buckets[d] holds entries
    std::uint64_t words = 0;                        // bit w set when nonempty[w] != 0
  };
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const {
      return a.time > b.time || (a.time == b.time && a.key > b.key);
    }
  };

  // Whether the head of run_ comes before the top of near_ (one of them is not empty).
  bool FromRun() const {
    if (head_ == run_.size()) return false;
    return near_.empty() || Later{}(near_.top(), run_[head_]);
  }

  // Into the wheel, relative to base_; level 0 (base_'s own block, only while spreading) is
  // filed under level 1 at base_'s digit, the first bucket Advance() looks at next.
  void Append(const Entry& e) {
    const auto t = static_cast<std::uint64_t>(e.time);
    const auto diff = t ^ static_cast<std::uint64_t>(base_);
    const int level = std::max(1, (63 - std::countl_zero(diff | 1)) / kDigitBits);
    const auto digit = static_cast<unsigned>(t >> (level * kDigitBits)) & kDigitMask;
    Level& l = levels_[static_cast<std::size_t>(level)];
    Bucket& b = l.buckets[digit];
    if (b.tail == nullptr || b.tail->count == Page::kEntries) {
      Page* page = NewPage();
      (b.tail == nullptr ? b.head : b.tail->next) = page;
      b.tail = page;
      l.nonempty[digit >> 6] |= std::uint64_t{1} << (digit & 63);
      l.words |= std::uint64_t{1} << (digit >> 6);
      levels_nonempty_ |= 1u << level;
    }
    b.tail->entries[b.tail->count++] = e;
  }

  Page* NewPage() {
    if (free_ == nullptr) {  // a slab of pages at a time, entries left uninitialised
      constexpr std::size_t kSlab = 64;
      pool_.push_back(std::unique_ptr<Page[]>(new Page[kSlab]));
      for (std::size_t i = 0; i < kSlab; ++i) pool_.back()[i].next = i + 1 < kSlab ? &pool_.back()[i + 1] : nullptr;
      free_ = &pool_.back()[0];
    }
    Page* page = free_;
    free_ = page->next;
    page->next = nullptr;
    page->count = 0;
    return page;
  }

  // Empties a bucket and returns its pages to the pool.
  Bucket Take(int level, unsigned digit) {
    Level& l = levels_[static_cast<std::size_t>(level)];
    const Bucket b = std::exchange(l.buckets[digit], Bucket{});
    if ((l.nonempty[digit >> 6] &= ~(std::uint64_t{1} << (digit & 63))) == 0) {
      if ((l.words &= ~(std::uint64_t{1} << (digit >> 6))) == 0) levels_nonempty_ &= ~(1u << level);
    }
    return b;
  }
  void Release(Bucket b) {
    b.tail->next = free_;
    free_ = b.head;
  }

  // The lowest digit with a non-empty bucket at `level` (which has one).
  int FirstDigit(int level) const {
    const Level& l = levels_[static_cast<std::size_t>(level)];
    const int w = std::countr_zero(l.words);
    return w * 64 + std::countr_zero(l.nonempty[static_cast<std::size_t>(w)]);
  }

  // run_ and near_ are drained and the wheel is not: brings the next non-empty block into run_.
  // The next block is that of the earliest entry of the first non-empty bucket of the lowest
  // non-empty level: every entry of that bucket shares base_'s digits above the bucket's level,
  // so relative to the new base_ (the start of that bucket's range, and at the end the block of
  // its earliest entry) the rest of the wheel keeps its levels and digits, and the
  // bucket's entries fall to levels below (a sparse queue's entry comes down in one step).
  void Advance() {
    for (;;) {
      const int level = std::countr_zero(levels_nonempty_);
      const Bucket from = Take(level, static_cast<unsigned>(FirstDigit(level)));
      if (from.head == from.tail && from.head->count == 1) {  // alone in its bucket: straight to run_
        const Entry e = from.head->entries[0];
        base_ = e.time & ~static_cast<std::int64_t>(kDigitMask);
        run_.clear();
        run_.push_back(e);
        head_ = 0;
        on_near_(e.key);
        Release(from);
        return;
      }
      if (level == 1) {
        base_ = from.head->entries[0].time & ~static_cast<std::int64_t>(kDigitMask);
        SortIntoRun(from);
        Release(from);
        return;
      }
      // Spread relative to the start of the bucket's range: the bucket's entries differ from it
      // only below `level`, so no scan for the earliest one is needed. Each page goes back to
      // the pool as soon as it is read, so the pages the spreading writes are mostly those it
      // has just read, still in cache.
      const int shift = level * kDigitBits;
      base_ = (from.head->entries[0].time >> shift) << shift;
      for (Page* b = from.head; b != nullptr;) {
        for (std::size_t i = 0; i < b->count; ++i) Append(b->entries[i]);  // to levels below, empty until now
        Page* const next = b->next;
        b->next = free_;
        free_ = b;
        b = next;
      }
    }
  }

  // run_ = block, sorted by time and, stably, by key (the block is in key order already).
  void SortIntoRun(const Bucket& bucket) {
    run_.clear();
    head_ = 0;
    for (const Page* b = bucket.head; b != nullptr; b = b->next) {
      for (std::size_t i = 0; i < b->count; ++i) run_.push_back(b->entries[i]);
    }
    if (run_.size() < kSmallSort) {
      for (std::size_t i = 1; i < run_.size(); ++i) {
        const Entry e = run_[i];
        std::size_t j = i;
        for (; j > 0 && run_[j - 1].time > e.time; --j) run_[j] = run_[j - 1];
        run_[j] = e;
      }
    } else {
      std::array<std::uint32_t, kDigits> start{};
      for (const Entry& e : run_) ++start[static_cast<std::size_t>(e.time) & kDigitMask];
      std::uint32_t sum = 0;
      for (std::uint32_t& s : start) sum += std::exchange(s, sum);
      sorted_.resize(run_.size());
      for (const Entry& e : run_) sorted_[start[static_cast<std::size_t>(e.time) & kDigitMask]++] = e;
      run_.swap(sorted_);
    }
    for (std::size_t i = 0; i < std::min(kLookAhead, run_.size()); ++i) on_near_(run_[i].key);
  }

  std::array<Level, kLevels> levels_;  // index 0 unused
  std::vector<std::unique_ptr<Page[]>> pool_;  // every page, owned
  Page* free_ = nullptr;                     // pages not in a bucket, linked by `next`
  std::vector<Entry> run_;                    // the current block, sorted; run_[head_] is next
  std::vector<Entry> sorted_;                 // scratch for the counting sort
  std::size_t head_ = 0;
  std::size_t size_ = 0;
  std::int64_t base_ = 0;  // start of the current block, a multiple of 256
  std::uint32_t levels_nonempty_ = 0;  // bit l set when level l holds entries
  std::priority_queue<Entry, std::vector<Entry>, Later> near_;
  [[no_unique_address]] OnNear on_near_{};
};

using RadixEventQueue = BasicRadixEventQueue<>;

}  // namespace dvpr
