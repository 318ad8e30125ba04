#pragma once
// One T per directed pair of nodes (src -> dst), holding only the pairs in use. A team of n
// robots has n^2 pairs: as a dense table that is 10^6 entries at 1000 robots, cleared and paged in
// before the first event although a run may never use most of them (docs/performance.md). Open
// addressing with linear probing on the pair's index src * nodes + dst, Fibonacci hashing, at most
// half full: a lookup is one probe in the common case, as cheap as a dense index once the entry
// is in cache. Small teams (at most kDenseNodes nodes) get the dense table itself: a slot per pair,
// the slot's index is the pair's, no probing and no rehashing; which pairs it holds is a bit per
// pair (1.2 kB at 100 nodes, in cache), so a lookup reads the value's cache line only, not a key's
// too (every copy of a message looks up three such tables: the network's counters, its link and
// its role bytes).
//
// References returned by At() stay valid until the next At() that inserts a pair.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "net_models/core/node_id.h"

namespace dvpr {

template <class T>
class PairMap {
 public:
  static constexpr int kDenseNodes = 256;  // 65 536 pairs

  explicit PairMap(int nodes) : nodes_(static_cast<std::uint64_t>(nodes)), dense_(nodes <= kDenseNodes) {
    if (nodes <= 0) throw std::invalid_argument("PairMap: need at least one node, got " + std::to_string(nodes));
    if (dense_) {
      held_.assign((nodes_ * nodes_ + 63) / 64, 0);
      values_.resize(nodes_ * nodes_);
    } else {
      Rehash(kMinCapacity);
    }
  }

  int nodes() const { return static_cast<int>(nodes_); }
  // Pairs held.
  std::size_t size() const { return size_; }

  // The pair's entry; a copy of `initial` is inserted if the pair has none.
  T& At(NodeId src, NodeId dst, const T& initial = T{}) {
    const std::uint64_t key = Key(src, dst);
    if (dense_) {
      std::uint64_t& word = held_[key / 64];
      const std::uint64_t bit = std::uint64_t{1} << (key % 64);
      if ((word & bit) == 0) {
        word |= bit;
        values_[key] = initial;
        ++size_;
      }
      return values_[key];
    }
    std::size_t i = Home(key);
    for (; keys_[i] != kEmpty; i = (i + 1) & mask_) {
      if (keys_[i] == key) return values_[i];
    }
    if (2 * (size_ + 1) > keys_.size()) {
      Rehash(2 * keys_.size());
      for (i = Home(key); keys_[i] != kEmpty; i = (i + 1) & mask_) {
      }
    }
    keys_[i] = key;
    values_[i] = initial;
    ++size_;
    return values_[i];
  }

  // The pair's entry, or null if the pair has none.
  const T* Find(NodeId src, NodeId dst) const {
    const std::uint64_t key = Key(src, dst);
    if (dense_) return Held(key) ? &values_[key] : nullptr;
    for (std::size_t i = Home(key); keys_[i] != kEmpty; i = (i + 1) & mask_) {
      if (keys_[i] == key) return &values_[i];
    }
    return nullptr;
  }

  // Calls f(src, dst, value) for every pair held, by source, then destination, ascending: the
  // order a dense table's rows would give, so outputs do not depend on the hashing.
  template <class F>
  void ForEachSorted(F&& f) const {
    if (dense_) {  // the slots are in key order already
      for (std::uint64_t key = 0; key < values_.size(); ++key) {
        if (Held(key)) f(NodeId(static_cast<int>(key / nodes_)), NodeId(static_cast<int>(key % nodes_)), values_[key]);
      }
      return;
    }
    std::vector<std::size_t> held;
    held.reserve(size_);
    for (std::size_t i = 0; i < keys_.size(); ++i) {
      if (keys_[i] != kEmpty) held.push_back(i);
    }
    std::sort(held.begin(), held.end(), [&](std::size_t a, std::size_t b) { return keys_[a] < keys_[b]; });
    for (const std::size_t i : held) {
      f(NodeId(static_cast<int>(keys_[i] / nodes_)), NodeId(static_cast<int>(keys_[i] % nodes_)), values_[i]);
    }
  }

  // Calls f(value) for every pair held, in no particular order (for sums).
  template <class F>
  void ForEach(F&& f) const {
    if (dense_) {
      for (std::uint64_t key = 0; key < values_.size(); ++key) {
        if (Held(key)) f(values_[key]);
      }
      return;
    }
    for (std::size_t i = 0; i < keys_.size(); ++i) {
      if (keys_[i] != kEmpty) f(values_[i]);
    }
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  static constexpr std::size_t kMinCapacity = 16;

  std::uint64_t Key(NodeId src, NodeId dst) const {
    const auto s = static_cast<std::uint64_t>(src.value);
    const auto d = static_cast<std::uint64_t>(dst.value);
    if (s >= nodes_ || d >= nodes_) {
      throw std::out_of_range("PairMap: pair " + std::to_string(src.value) + "->" + std::to_string(dst.value) +
                              " outside [0, " + std::to_string(nodes_) + ")");
    }
    return s * nodes_ + d;
  }
  bool Held(std::uint64_t key) const { return (held_[key / 64] >> (key % 64) & 1) != 0; }
  // Fibonacci hashing: consecutive pair indices land far apart.
  std::size_t Home(std::uint64_t key) const {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  void Rehash(std::size_t capacity) {
    std::vector<std::uint64_t> old_keys(capacity, kEmpty);
    std::vector<T> old_values(capacity);
    old_keys.swap(keys_);
    old_values.swap(values_);
    mask_ = capacity - 1;
    shift_ = 64 - std::countr_zero(capacity);
    for (std::size_t j = 0; j < old_keys.size(); ++j) {
      if (old_keys[j] == kEmpty) continue;
      std::size_t i = Home(old_keys[j]);
      while (keys_[i] != kEmpty) i = (i + 1) & mask_;
      keys_[i] = old_keys[j];
      values_[i] = std::move(old_values[j]);
    }
  }

  std::uint64_t nodes_;
  bool dense_;  // a slot per pair, at index src * nodes + dst
  std::vector<std::uint64_t> held_;  // dense: bit key % 64 of word key / 64 set when the pair is held
  std::vector<std::uint64_t> keys_;  // open addressing: capacity a power of two; kEmpty: free
  std::vector<T> values_;
  std::size_t mask_ = 0;
  int shift_ = 64;
  std::size_t size_ = 0;
};

}  // namespace dvpr
