// GrowableArray: values survive every growth, including the switch from malloc to a memory
// mapping (256 KiB) and growth of a mapping by mremap; copies are deep, moves take the storage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "agents/growable_array.h"

namespace dvpr {
namespace {

// 3 x 2^20 values of 4 bytes: 12 MiB, grown one value at a time through every regime.
TEST(GrowableArray, KeepsEveryValueThroughMallocAndMappedGrowth) {
  GrowableArray<std::uint32_t> a;
  std::vector<std::uint32_t> reference;
  for (std::uint32_t i = 0; i < (3u << 20); ++i) {
    const std::uint32_t v = i * 2654435761u;  // distinct values, not a pattern of zeros
    a.push_back(v);
    reference.push_back(v);
  }
  ASSERT_EQ(a.size(), reference.size());
  EXPECT_TRUE(std::equal(a.begin(), a.end(), reference.begin()));
}

TEST(GrowableArray, AppendResizeAndClear) {
  GrowableArray<float> a;
  EXPECT_TRUE(a.empty());
  const float row[3] = {1.5f, -2.0f, 3.25f};
  a.Append(row, 3);
  a.resize(5);  // two zeros
  EXPECT_EQ(std::vector<float>(a.begin(), a.end()), (std::vector<float>{1.5f, -2.0f, 3.25f, 0.0f, 0.0f}));
  a.resize(2);
  EXPECT_EQ(a.back(), -2.0f);
  a.resize(4);  // the values past the old size are zero again, not what was there before
  EXPECT_EQ(std::vector<float>(a.begin(), a.end()), (std::vector<float>{1.5f, -2.0f, 0.0f, 0.0f}));
  a.clear();
  EXPECT_EQ(a.size(), 0u);
  a.push_back(7.0f);
  EXPECT_EQ(a[0], 7.0f);
}

TEST(GrowableArray, ResizeOfAMappedBufferZeroesTheNewValues) {
  GrowableArray<std::uint16_t> a;
  a.resize(300000);  // 600 kB: a mapping
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = 0xffff;
  a.resize(100);
  a.resize(400000);  // grows the mapping; 100..400000 must read zero
  std::size_t nonzero = 0;
  for (std::size_t i = 100; i < a.size(); ++i) nonzero += a[i] != 0;
  EXPECT_EQ(nonzero, 0u);
  EXPECT_EQ(a[99], 0xffff);
}

TEST(GrowableArray, CopiesAreDeepAndMovesTakeTheStorage) {
  GrowableArray<int> a;
  for (int i = 0; i < 100000; ++i) a.push_back(i);  // 400 kB: a mapping
  GrowableArray<int> b(a);
  b[5] = -1;
  EXPECT_EQ(a[5], 5);
  GrowableArray<int> c;
  c = a;
  EXPECT_EQ(c.size(), 100000u);
  EXPECT_EQ(c[99999], 99999);
  const int* storage = a.data();
  GrowableArray<int> d(std::move(a));
  EXPECT_EQ(d.data(), storage);
  EXPECT_EQ(d.size(), 100000u);
  GrowableArray<int> e;
  e.push_back(1);
  e = std::move(d);
  EXPECT_EQ(e.data(), storage);
  EXPECT_EQ(e[12345], 12345);
}

}  // namespace
}  // namespace dvpr
