// The grouped search of a large store (issue 15) against the search that looks at every row:
// the same match, the same distance bit for bit, the same tie; and on integer data, where
// every distance is exact in float, against a brute force in double written here.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "agents/descriptor_index.h"

namespace dvpr {
namespace {

std::uint32_t Bits(float f) {
  std::uint32_t u = 0;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

void ExpectSameResult(const IncrementalIndex& index, const float* q, FrameId frame, int window) {
  const IndexSearchResult fast = index.Search(q, frame, window);
  const IndexSearchResult all = index.SearchAll(q, frame, window);
  EXPECT_EQ(fast.comparisons, all.comparisons);
  ASSERT_EQ(fast.best.has_value(), all.best.has_value());
  if (!all.best) return;
  EXPECT_EQ(fast.best->robot, all.best->robot);
  EXPECT_EQ(fast.best->frame, all.best->frame);
  EXPECT_EQ(Bits(fast.best->distance), Bits(all.best->distance)) << fast.best->distance << " vs " << all.best->distance;
}

// Rows along a smooth random walk (as descriptors along a trajectory), variance falling with the
// dimension (as after PCA), plus noise.
std::vector<float> WalkRows(int n, int dim, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<float> normal(0.0f, 1.0f);
  std::vector<float> pos(static_cast<std::size_t>(dim), 0.0f), rows;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < dim; ++j) {
      const float scale = 1.0f / std::sqrt(static_cast<float>(j + 1));
      pos[static_cast<std::size_t>(j)] += 0.1f * scale * normal(rng);
      rows.push_back(pos[static_cast<std::size_t>(j)] + 0.05f * scale * normal(rng));
    }
  }
  return rows;
}

TEST(ExactSearch, GroupedSearchMatchesTheFullScanBitForBit) {
  for (const int dim : {128, 130, 13, 3}) {
    const int n = 3000;  // grouped from 512 rows, regrouped at 1024 and 2048
    const std::vector<float> rows = WalkRows(n, dim, 11 + static_cast<std::uint64_t>(dim));
    const std::vector<float> queries = WalkRows(200, dim, 99);
    IncrementalIndex index(dim);
    for (int i = 0; i < n; ++i) {
      index.Add(RobotId(i % 7), FrameId(i), rows.data() + static_cast<std::size_t>(i) * static_cast<std::size_t>(dim));
      if (i % 97 != 0 || i < 400) continue;
      const float* own = rows.data() + static_cast<std::size_t>(i / 2) * static_cast<std::size_t>(dim);
      ExpectSameResult(index, own, FrameId(i / 2), 0);                    // a stored row: distance ~0
      ExpectSameResult(index, own, FrameId(i / 2), 25);                   // its neighbours suppressed
      ExpectSameResult(index, queries.data() + static_cast<std::size_t>(i % 200) * static_cast<std::size_t>(dim),
                       FrameId(100000), 0);                               // a place never seen
    }
  }
}

TEST(ExactSearch, TheLastRowOfEveryStoreSizeGetsTheFullScansDistance) {
  // The last row is where Eigen's product sums a row differently (single-row tail); a query a
  // hair from it makes it the match for every store size around the grouping threshold.
  for (const int dim : {3, 13, 130}) {
    const std::vector<float> rows = WalkRows(620, dim, 5);
    IncrementalIndex index(dim);
    for (int i = 0; i < 620; ++i) {
      const float* row = rows.data() + static_cast<std::size_t>(i) * static_cast<std::size_t>(dim);
      index.Add(RobotId(0), FrameId(i), row);
      if (i < 500) continue;
      std::vector<float> q(row, row + dim);
      q[0] += 1e-3f;
      ExpectSameResult(index, q.data(), FrameId(100000), 0);
      ASSERT_EQ(index.Search(q.data(), FrameId(100000), 0).best->frame, FrameId(i));
    }
  }
}

TEST(ExactSearch, IntegerDataTiesGoToTheFirstAddedAsABruteForceInDouble) {
  // Small integers: every distance is exact in float, and many rows tie (duplicates and rows
  // symmetric about the query). The expected match is the lowest index at the minimum exact
  // distance, found here in double.
  const int dim = 8, n = 2000;
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> coord(-2, 2);
  std::vector<float> rows(static_cast<std::size_t>(n * dim));
  for (float& x : rows) x = static_cast<float>(coord(rng));
  IncrementalIndex index(dim);
  for (int i = 0; i < n; ++i) index.Add(RobotId(i % 5), FrameId(3 * i), rows.data() + i * dim);
  for (int t = 0; t < 300; ++t) {
    std::vector<float> q(dim);
    for (float& x : q) x = static_cast<float>(coord(rng));
    const int frame = static_cast<int>(rng() % (3 * n));
    const int window = static_cast<int>(rng() % 40);
    int expected = -1;
    double best = 0;
    for (int i = 0; i < n; ++i) {
      if (std::abs(3 * i - frame) <= window) continue;
      double d = 0;
      for (int j = 0; j < dim; ++j) d += std::pow(static_cast<double>(rows[i * dim + j]) - q[j], 2);
      if (expected < 0 || d < best) { expected = i; best = d; }
    }
    const IndexSearchResult r = index.Search(q.data(), FrameId(frame), window);
    ASSERT_TRUE(r.best.has_value());
    EXPECT_EQ(r.best->frame, FrameId(3 * expected));
    EXPECT_EQ(r.best->robot, RobotId(expected % 5));
    EXPECT_EQ(static_cast<double>(r.best->distance), best);
    ExpectSameResult(index, q.data(), FrameId(frame), window);
  }
}

TEST(ExactSearch, AfterRemoveIfTheGroupedSearchStillMatches) {
  const int dim = 16, n = 1500;
  const std::vector<float> rows = WalkRows(n, dim, 8);
  IncrementalIndex index(dim);
  for (int i = 0; i < n; ++i) index.Add(RobotId(0), FrameId(i), rows.data() + i * dim);
  index.RemoveIf([](std::size_t i) { return i % 3 == 0; });
  ASSERT_EQ(index.size(), 1000u);
  for (int i = 0; i < 60; ++i) index.Add(RobotId(1), FrameId(n + i), rows.data() + (i * 7) * dim);
  for (int i = 0; i < n; i += 37) ExpectSameResult(index, rows.data() + i * dim, FrameId(i), 2);
}

}  // namespace
}  // namespace dvpr
