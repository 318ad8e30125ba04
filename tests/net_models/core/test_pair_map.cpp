// PairMap against std::map: the same entries after many inserts (through several rehashes),
// sorted iteration in (source, destination) order, and the errors.
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "net_models/core/pair_map.h"

namespace dvpr {
namespace {

TEST(PairMapTest, StartsEmptyAndFindsNothing) {
  const PairMap<int> m(4);
  EXPECT_EQ(m.size(), 0u);
  EXPECT_EQ(m.Find(NodeId(0), NodeId(1)), nullptr);
  int visits = 0;
  m.ForEachSorted([&](NodeId, NodeId, int) { ++visits; });
  EXPECT_EQ(visits, 0);
}

TEST(PairMapTest, InsertsTheInitialValueOnceAndKeepsUpdates) {
  PairMap<int> m(3);
  EXPECT_EQ(m.At(NodeId(2), NodeId(0), 7), 7);
  m.At(NodeId(2), NodeId(0), 7) += 5;
  EXPECT_EQ(m.At(NodeId(2), NodeId(0), 100), 12);  // present: `initial` is not used again
  ASSERT_NE(m.Find(NodeId(2), NodeId(0)), nullptr);
  EXPECT_EQ(*m.Find(NodeId(2), NodeId(0)), 12);
  EXPECT_EQ(m.Find(NodeId(0), NodeId(2)), nullptr);  // directed: the reverse pair is another
  EXPECT_EQ(m.size(), 1u);
}

// 30 000 random increments: with 1000 nodes (hashed: 10^6 possible pairs, the table rehashes from
// 16 to 65 536 slots) and with 100 (dense: a slot per pair). Every count and the visiting order
// must equal std::map's.
class PairMapVsMapTest : public ::testing::TestWithParam<int> {};

TEST_P(PairMapVsMapTest, MatchesAnOrderedMap) {
  const int nodes = GetParam();
  PairMap<std::int64_t> m(nodes);
  std::map<std::pair<int, int>, std::int64_t> reference;
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> node(0, nodes - 1);
  for (int i = 0; i < 30000; ++i) {
    const int s = node(rng);
    const int d = i % 3 == 0 ? (s + 1) % nodes : node(rng);  // many repeats of some pairs
    m.At(NodeId(s), NodeId(d)) += i;
    reference[{s, d}] += i;
  }
  ASSERT_EQ(m.size(), reference.size());
  std::vector<std::pair<std::pair<int, int>, std::int64_t>> visited;
  m.ForEachSorted([&](NodeId s, NodeId d, std::int64_t v) { visited.push_back({{s.value, d.value}, v}); });
  const std::vector<std::pair<std::pair<int, int>, std::int64_t>> expected(reference.begin(), reference.end());
  EXPECT_EQ(visited, expected);
  std::int64_t sum = 0;
  m.ForEach([&](std::int64_t v) { sum += v; });
  EXPECT_EQ(sum, std::int64_t{30000} * 29999 / 2);  // 0 + 1 + ... + 29 999
  for (const auto& [pair, v] : reference) {
    const std::int64_t* found = m.Find(NodeId(pair.first), NodeId(pair.second));
    ASSERT_NE(found, nullptr);
    EXPECT_EQ(*found, v);
  }
}

INSTANTIATE_TEST_SUITE_P(Layouts, PairMapVsMapTest, ::testing::Values(100, 1000),
                         [](const auto& info) { return std::to_string(info.param) + "Nodes"; });

TEST(PairMapTest, ReportsPairsOutsideTheTeam) {
  PairMap<int> m(3);
  EXPECT_THROW(m.At(NodeId(3), NodeId(0)), std::out_of_range);
  EXPECT_THROW((void)m.Find(NodeId(0), NodeId(-1)), std::out_of_range);
  EXPECT_THROW(PairMap<int>(0), std::invalid_argument);
}

}  // namespace
}  // namespace dvpr
