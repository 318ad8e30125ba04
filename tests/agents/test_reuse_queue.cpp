// ReuseQueue (agents/reuse_queue.h): first in, first out through wrap-around and growth, and a
// slot's buffer handed back to a later Push instead of a new one.
#include "agents/reuse_queue.h"

#include <gtest/gtest.h>

#include <deque>
#include <vector>

namespace dvpr {
namespace {

struct Item {
  int value = 0;
  std::vector<int> buffer;
};

TEST(ReuseQueueTest, IsFirstInFirstOutThroughWrapAroundAndGrowth) {
  ReuseQueue<Item> q;
  std::deque<int> expected;
  Item out;
  int next = 0;
  // Pushes 3, pops 2, repeatedly: the ring wraps and grows (8, 16, 32 slots) with elements in it.
  for (int round = 0; round < 20; ++round) {
    for (int i = 0; i < 3; ++i) {
      q.Push().value = next;
      expected.push_back(next++);
    }
    for (int i = 0; i < 2; ++i) {
      q.PopInto(out);
      EXPECT_EQ(out.value, expected.front());
      expected.pop_front();
    }
    EXPECT_EQ(q.size(), expected.size());
  }
  while (!q.empty()) {
    q.PopInto(out);
    EXPECT_EQ(out.value, expected.front());
    expected.pop_front();
  }
  EXPECT_TRUE(expected.empty());
  EXPECT_EQ(next, 60);
}

// Push a, b; pop a into `out` (which held buffer x): the slot now holds x. Push c, d, ... until
// the ring comes round to that slot (8 slots): the 8th push after a is in a's slot and finds x.
TEST(ReuseQueueTest, APoppedSlotKeepsTheCallersOldBufferForALaterPush) {
  ReuseQueue<Item> q;
  Item& a = q.Push();
  a.value = 1;
  a.buffer = {1, 1};
  q.Push().value = 2;
  Item out;
  out.buffer.reserve(100);
  out.buffer = {7, 7, 7};
  const int* x = out.buffer.data();
  q.PopInto(out);
  EXPECT_EQ(out.value, 1);
  EXPECT_EQ(out.buffer, (std::vector<int>{1, 1}));
  // Slots 2..7 are new; the next push after them is slot 0, a's, which now holds x.
  for (int i = 0; i < 6; ++i) EXPECT_TRUE(q.Push().buffer.empty());
  Item& reused = q.Push();
  EXPECT_EQ(reused.buffer.data(), x);
  EXPECT_EQ(reused.buffer, (std::vector<int>{7, 7, 7}));
  EXPECT_EQ(reused.buffer.capacity(), 100u);
  EXPECT_EQ(q.size(), 8u);
}

TEST(ReuseQueueTest, ClearEmptiesAndTheNextPopIsTheNextPush) {
  ReuseQueue<Item> q;
  for (int i = 0; i < 5; ++i) q.Push().value = i;
  Item out;
  q.PopInto(out);
  q.clear();
  EXPECT_TRUE(q.empty());
  EXPECT_EQ(q.size(), 0u);
  q.Push().value = 42;
  q.PopInto(out);
  EXPECT_EQ(out.value, 42);
  EXPECT_TRUE(q.empty());
}

// ForEach visits the queued elements front to back, also across the ring's wrap-around, and
// may change them.
TEST(ReuseQueueTest, ForEachVisitsFrontToBackAndMayChangeThem) {
  ReuseQueue<Item> q;
  Item out;
  for (int i = 0; i < 6; ++i) q.Push().value = i;
  for (int i = 0; i < 4; ++i) q.PopInto(out);
  for (int i = 6; i < 11; ++i) q.Push().value = i;  // 8 slots: 8, 9, 10 wrap to the start
  std::vector<int> seen;
  q.ForEach([&](Item& item) {
    seen.push_back(item.value);
    item.value *= 10;
  });
  EXPECT_EQ(seen, (std::vector<int>{4, 5, 6, 7, 8, 9, 10}));
  std::vector<int> popped;
  while (!q.empty()) {
    q.PopInto(out);
    popped.push_back(out.value);
  }
  EXPECT_EQ(popped, (std::vector<int>{40, 50, 60, 70, 80, 90, 100}));
}

}  // namespace
}  // namespace dvpr
