// SlotPool: new slots numbered from 0, reuse last-freed-first, a reused slot's T as it was left
// (a vector's contents and capacity), and the counts. Every expected value is worked by hand in
// the comments: `free` is the stack of released slots, its back the next Acquire.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "net_models/core/slot_pool.h"

namespace dvpr {
namespace {

TEST(SlotPoolTest, StartsEmpty) {
  const SlotPool<int> pool;
  EXPECT_EQ(pool.size(), 0u);
  EXPECT_EQ(pool.in_use(), 0u);
}

TEST(SlotPoolTest, NewSlotsAreNumberedInOrderAndDefault) {
  SlotPool<int> pool;
  EXPECT_EQ(pool.Acquire(), 0u);
  EXPECT_EQ(pool.Acquire(), 1u);
  EXPECT_EQ(pool.Acquire(), 2u);
  EXPECT_EQ(pool.size(), 3u);
  EXPECT_EQ(pool.in_use(), 3u);
  EXPECT_EQ(pool[0], 0);  // value-initialised
  EXPECT_EQ(pool[2], 0);
}

// Slots 0..3 made; release 1, 3, 0 (free = [1, 3, 0]); then 0 and 3 come back; release 2
// (free = [1, 2]); 2 and 1 come back; the free stack is empty, so the next is a new slot 4.
TEST(SlotPoolTest, ReusesTheLastReleasedSlotFirst) {
  SlotPool<int> pool;
  for (std::uint32_t expected = 0; expected < 4; ++expected) EXPECT_EQ(pool.Acquire(), expected);
  pool.Release(1);
  pool.Release(3);
  pool.Release(0);
  EXPECT_EQ(pool.size(), 4u);
  EXPECT_EQ(pool.in_use(), 1u);  // slot 2
  EXPECT_EQ(pool.Acquire(), 0u);
  EXPECT_EQ(pool.Acquire(), 3u);
  EXPECT_EQ(pool.in_use(), 3u);  // 0, 2, 3
  pool.Release(2);
  EXPECT_EQ(pool.in_use(), 2u);  // 0, 3
  EXPECT_EQ(pool.Acquire(), 2u);
  EXPECT_EQ(pool.Acquire(), 1u);
  EXPECT_EQ(pool.size(), 4u);  // no slot made while one was free
  EXPECT_EQ(pool.in_use(), 4u);
  EXPECT_EQ(pool.Acquire(), 4u);
  EXPECT_EQ(pool.size(), 5u);
  EXPECT_EQ(pool.in_use(), 5u);
}

TEST(SlotPoolTest, AReusedSlotKeepsItsValue) {
  SlotPool<int> pool;
  const std::uint32_t a = pool.Acquire();
  const std::uint32_t b = pool.Acquire();
  pool[a] = 7;
  pool[b] = 9;
  pool.Release(a);
  EXPECT_EQ(pool.Acquire(), a);
  EXPECT_EQ(pool[a], 7);  // not reset: the caller sets what it uses
  const SlotPool<int>& view = pool;
  EXPECT_EQ(view[b], 9);
}

// The point of the pool for the network and the MACs: a released slot's vector keeps its buffer,
// so the next message in that slot allocates nothing.
TEST(SlotPoolTest, AReusedSlotKeepsItsVectorsCapacityAndContents) {
  SlotPool<std::vector<int>> pool;
  const std::uint32_t slot = pool.Acquire();
  pool[slot].reserve(100);
  pool[slot].assign({1, 2, 3});
  const int* buffer = pool[slot].data();
  const std::size_t capacity = pool[slot].capacity();
  pool.Release(slot);
  ASSERT_EQ(pool.Acquire(), slot);
  EXPECT_EQ(pool[slot], (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(pool[slot].data(), buffer);
  EXPECT_EQ(pool[slot].capacity(), capacity);
  pool[slot].clear();  // as a user does before refilling it
  EXPECT_EQ(pool[slot].capacity(), capacity);
}

// New slots may move the Ts (index again after an Acquire), but not the buffers they own: a span
// over a slot's vector taken before stays valid (wifi's EndAir keeps TransmissionLedger::Destinations
// across sends that open messages).
TEST(SlotPoolTest, GrowingKeepsTheBuffersTheSlotsOwn) {
  SlotPool<std::vector<int>> pool;
  const std::uint32_t first = pool.Acquire();
  pool[first].assign({4, 5, 6});
  const int* buffer = pool[first].data();
  for (std::uint32_t expected = 1; expected <= 1000; ++expected) {  // the storage reallocates ~10 times
    ASSERT_EQ(pool.Acquire(), expected);
  }
  EXPECT_EQ(pool.size(), 1001u);
  EXPECT_EQ(pool[first].data(), buffer);
  EXPECT_EQ(pool[first], (std::vector<int>{4, 5, 6}));
}

}  // namespace
}  // namespace dvpr
