// The pruned search (IncrementalIndex::Search) against two references: a brute force in double
// written here (independent of the index's code), and the model's full matrix-vector product
// (SearchFullScan, the definition of the simulated distances): same entry, same float bits.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "agents/algorithms/descriptor_index.h"
#include "agents/algorithms/gemv_row.h"

namespace dvpr {
namespace {

struct Stored {
  int dim = 0;
  std::vector<float> rows;  // row-major
  std::vector<int> frames;
};

// Index of the nearest row outside the window in double arithmetic, ties to the lowest index.
std::optional<std::size_t> BruteForce(const Stored& s, const float* q, int query_frame, int window) {
  std::optional<std::size_t> best;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < s.frames.size(); ++i) {
    if (std::abs(s.frames[i] - query_frame) <= window) continue;
    double d = 0.0;
    for (int j = 0; j < s.dim; ++j) {
      const double diff = static_cast<double>(s.rows[i * s.dim + j]) - static_cast<double>(q[j]);
      d += diff * diff;
    }
    if (d < best_d) best_d = d, best = i;
  }
  return best;
}

// Descriptors with the model's shape: variance of dimension j falls as 1 / (j + 1).
std::vector<float> Gaussian(std::mt19937& rng, int count, int dim) {
  std::normal_distribution<float> normal(0.0f, 1.0f);
  std::vector<float> v(static_cast<std::size_t>(count) * dim);
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < dim; ++j) v[i * dim + j] = normal(rng) / std::sqrt(static_cast<float>(j + 1));
  }
  return v;
}

// Small integers: every float product and sum is exact, so the float search must pick exactly
// the double brute force's row, and distances tie often.
std::vector<float> Integers(std::mt19937& rng, int count, int dim, int range) {
  std::uniform_int_distribution<int> value(-range, range);
  std::vector<float> v(static_cast<std::size_t>(count) * dim);
  for (auto& x : v) x = static_cast<float>(value(rng));
  return v;
}

Stored Fill(IncrementalIndex& index, const std::vector<float>& rows, int dim) {
  Stored s{dim, rows, {}};
  for (std::size_t i = 0; i < rows.size() / dim; ++i) {
    s.frames.push_back(static_cast<int>(i) * 3);  // frames 3 apart, windows cut out runs of rows
    index.Add(RobotId(static_cast<std::int32_t>(i % 7)), FrameId(s.frames.back()), &rows[i * dim]);
  }
  return s;
}

// Eigen's product of `data` (rows x dim, row-major) with q: the values the kernels must equal.
Eigen::VectorXf FullProduct(const std::vector<float>& data, int rows, int dim, const std::vector<float>& q) {
  using RowMajor = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  Eigen::VectorXf full(rows);
  full.noalias() = Eigen::Map<const RowMajor>(data.data(), rows, dim) * Eigen::Map<const Eigen::VectorXf>(q.data(), dim);
  return full;
}

// The pruned search equals the full scan bit for bit (entry and distance).
void ExpectSameAsFullScan(const IncrementalIndex& index, const float* q, int frame, int window) {
  const IndexSearchResult fast = index.Search(q, FrameId(frame), window);
  const IndexSearchResult full = index.SearchFullScan(q, FrameId(frame), window);
  EXPECT_EQ(fast.comparisons, full.comparisons);
  ASSERT_EQ(fast.best.has_value(), full.best.has_value());
  if (!full.best) return;
  EXPECT_EQ(fast.best->frame, full.best->frame);
  EXPECT_EQ(fast.best->robot, full.best->robot);
  EXPECT_EQ(std::bit_cast<std::uint32_t>(fast.best->distance), std::bit_cast<std::uint32_t>(full.best->distance));
}

class FastSearchByWidth : public ::testing::TestWithParam<int> {};

TEST_P(FastSearchByWidth, GemvRowEqualsTheFullProductBitForBit) {
  const int dim = GetParam();
  std::mt19937 rng(11);
  const std::vector<float> q = Gaussian(rng, 1, dim);
  for (int rows : {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 23, 100, 257}) {
    const std::vector<float> data = Gaussian(rng, rows, dim);
    const Eigen::VectorXf full = FullProduct(data, rows, dim, q);
    for (int i = 0; i < rows; ++i) {
      const float one = GemvRowAsInFullProduct(data.data(), rows, dim, i, q.data());
      ASSERT_EQ(std::bit_cast<std::uint32_t>(one), std::bit_cast<std::uint32_t>(full[i]))
          << "rows " << rows << " row " << i;
    }
  }
}

TEST_P(FastSearchByWidth, RandomDataMatchesFullScanAndBruteForce) {
  const int dim = GetParam();
  std::mt19937 rng(static_cast<unsigned>(dim));
  IncrementalIndex index(dim);
  const Stored s = Fill(index, Gaussian(rng, 601, dim), dim);
  const std::vector<float> queries = Gaussian(rng, 40, dim);
  for (int k = 0; k < 40; ++k) {
    const float* q = &queries[static_cast<std::size_t>(k) * dim];
    for (int window : {0, 30, 900, 2000}) {
      const int frame = k * 45;
      ExpectSameAsFullScan(index, q, frame, window);
      const auto expected = BruteForce(s, q, frame, window);
      const auto r = index.Search(q, FrameId(frame), window);
      ASSERT_EQ(r.best.has_value(), expected.has_value());
      // Random floats: no two rows are within float rounding of each other here.
      if (expected) {
        EXPECT_EQ(r.best->frame, FrameId(s.frames[*expected]));
      }
    }
  }
}

TEST_P(FastSearchByWidth, IntegerDataFullOfTiesMatchesBruteForceExactly) {
  const int dim = GetParam();
  std::mt19937 rng(static_cast<unsigned>(100 + dim));
  IncrementalIndex index(dim);
  const Stored s = Fill(index, Integers(rng, 500, dim, 1), dim);
  const std::vector<float> queries = Integers(rng, 60, dim, 1);
  for (int k = 0; k < 60; ++k) {
    const float* q = &queries[static_cast<std::size_t>(k) * dim];
    for (int window : {0, 10, 300}) {
      const int frame = k * 25;
      const auto expected = BruteForce(s, q, frame, window);
      const auto r = index.Search(q, FrameId(frame), window);
      ASSERT_TRUE(expected.has_value());
      ASSERT_TRUE(r.best.has_value());
      EXPECT_EQ(r.best->frame, FrameId(s.frames[*expected])) << "query " << k << " window " << window;
      double d = 0.0;  // integers: the float distance is exact
      for (int j = 0; j < dim; ++j) d += std::pow(s.rows[*expected * dim + j] - q[j], 2);
      EXPECT_EQ(static_cast<double>(r.best->distance), d);
      ExpectSameAsFullScan(index, q, frame, window);
    }
  }
}

TEST_P(FastSearchByWidth, NearTiesWithinFloatRoundingResolveAsTheFullScan) {
  // Copies of one row, each nudged by one unit in the last place in a few values: their model
  // distances are equal or a few ulps apart, and float rounding of the expansion decides.
  const int dim = GetParam();
  std::mt19937 rng(static_cast<unsigned>(7 + dim));
  const std::vector<float> base = Gaussian(rng, 1, dim);
  std::vector<float> rows;
  std::uniform_int_distribution<int> pick(0, dim - 1), coin(0, 1);
  for (int i = 0; i < 300; ++i) {
    std::vector<float> r = base;
    for (int t = 0; t < 3; ++t) {
      float& x = r[static_cast<std::size_t>(pick(rng))];
      x = std::nextafter(x, coin(rng) ? 1e9f : -1e9f);
    }
    rows.insert(rows.end(), r.begin(), r.end());
  }
  IncrementalIndex index(dim);
  Fill(index, rows, dim);
  for (int k = 0; k < 30; ++k) {
    std::vector<float> q = base;
    q[static_cast<std::size_t>(pick(rng))] += 1e-3f * static_cast<float>(k);
    for (int window : {0, 20, 400}) ExpectSameAsFullScan(index, q.data(), k * 30, window);
  }
}

TEST_P(FastSearchByWidth, RemovalsKeepOrderAndAnswers) {
  const int dim = GetParam();
  std::mt19937 rng(static_cast<unsigned>(55 + dim));
  IncrementalIndex index(dim);
  Stored s = Fill(index, Integers(rng, 400, dim, 2), dim);
  const std::vector<float> queries = Integers(rng, 20, dim, 2);
  for (int k = 0; k < 10; ++k) index.Search(&queries[static_cast<std::size_t>(k) * dim], FrameId(k), 5);  // set hints
  index.RemoveIf([](std::size_t i) { return i % 3 == 1; });
  Stored kept{dim, {}, {}};
  for (std::size_t i = 0; i < s.frames.size(); ++i) {
    if (i % 3 == 1) continue;
    kept.frames.push_back(s.frames[i]);
    kept.rows.insert(kept.rows.end(), s.rows.begin() + static_cast<std::ptrdiff_t>(i * dim),
                     s.rows.begin() + static_cast<std::ptrdiff_t>((i + 1) * dim));
  }
  ASSERT_EQ(index.size(), kept.frames.size());
  for (int k = 0; k < 20; ++k) {
    const float* q = &queries[static_cast<std::size_t>(k) * dim];
    const auto expected = BruteForce(kept, q, k * 50, 12);
    const auto r = index.Search(q, FrameId(k * 50), 12);
    ASSERT_TRUE(r.best.has_value());
    EXPECT_EQ(r.best->frame, FrameId(kept.frames[*expected]));
    ExpectSameAsFullScan(index, q, k * 50, 12);
  }
}

// The screen keeps every row in half precision (2^-11 relative rounding, 5e-4 at magnitude 1):
// rows that differ from each other by less than that look alike to it, and only the bound's
// allowance for each row's rounding error keeps the winner from being screened out.
TEST_P(FastSearchByWidth, RowsAlikeInHalfPrecisionResolveAsTheFullScan) {
  const int dim = GetParam();
  std::mt19937 rng(static_cast<unsigned>(300 + dim));
  const std::vector<float> base = Gaussian(rng, 1, dim);
  std::vector<float> rows = Gaussian(rng, 150, dim);  // far rows first: they set a loose best
  std::uniform_real_distribution<float> nudge(-3e-4f, 3e-4f);
  for (int i = 0; i < 250; ++i) {
    for (float x : base) rows.push_back(x + nudge(rng));
  }
  IncrementalIndex index(dim);
  const Stored s = Fill(index, rows, dim);
  for (int k = 0; k < 40; ++k) {
    std::vector<float> q = base;
    for (float& x : q) x += nudge(rng);
    for (int window : {0, 60, 500}) {
      ExpectSameAsFullScan(index, q.data(), k * 25, window);
      const auto expected = BruteForce(s, q.data(), k * 25, window);
      const auto r = index.Search(q.data(), FrameId(k * 25), window);
      ASSERT_TRUE(expected.has_value() && r.best.has_value());
      // The double brute force may differ from the float model only between rows whose
      // distances are within the model's rounding (dim units of 2^-24 of the squared norms,
      // for each of the two rows) of each other.
      const auto row = [&](std::size_t i) { return &s.rows[i * static_cast<std::size_t>(dim)]; };
      const auto squared = [&](const float* a, const float* b) {
        double sum = 0.0;
        for (int j = 0; j < dim; ++j) sum += std::pow(double{a[j]} - (b ? double{b[j]} : 0.0), 2);
        return sum;
      };
      const float* found = row(static_cast<std::size_t>(r.best->frame.value / 3));
      const double rounding = 2.0 * dim * 0x1.0p-24 * (squared(found, nullptr) + squared(q.data(), nullptr));
      EXPECT_LE(squared(found, q.data()) - squared(row(*expected), q.data()), rounding)
          << "query " << k << " window " << window;
    }
  }
}

// Values a half cannot hold: above its largest finite value (65504) the copy is infinite, below
// 6.1e-5 it is subnormal or zero (large relative error). Search still equals the full scan.
TEST_P(FastSearchByWidth, ValuesOutsideHalfPrecisionsRangeMatchFullScanAndBruteForce) {
  const int dim = GetParam();
  for (const float scale : {1e6f, 1e-6f, 1e-30f}) {
    std::mt19937 rng(static_cast<unsigned>(dim) + 17);
    std::vector<float> rows = Gaussian(rng, 300, dim);
    for (float& x : rows) x *= scale;
    IncrementalIndex index(dim);
    const Stored s = Fill(index, rows, dim);
    std::vector<float> queries = Gaussian(rng, 20, dim);
    for (float& x : queries) x *= scale;
    for (int k = 0; k < 20; ++k) {
      const float* q = &queries[static_cast<std::size_t>(k) * dim];
      ExpectSameAsFullScan(index, q, k * 40, 30);
      const auto expected = BruteForce(s, q, k * 40, 30);
      const auto r = index.Search(q, FrameId(k * 40), 30);
      ASSERT_TRUE(expected.has_value() && r.best.has_value());
      if (scale > 1e-20f) {  // at 1e-30 the float distances underflow: only the full scan decides
        EXPECT_EQ(r.best->frame, FrameId(s.frames[*expected])) << "scale " << scale << " query " << k;
      }
    }
  }
}

// One row with a value beyond the half range among ordinary rows: the store's screen has no
// finite bound for it and must not drop it when it is the nearest.
TEST(FastSearch, ARowBeyondHalfRangeIsStillFoundWhenNearest) {
  const int dim = 128;
  std::mt19937 rng(5);
  std::vector<float> rows = Gaussian(rng, 200, dim);
  std::vector<float> far(static_cast<std::size_t>(dim), 0.0f);
  far[0] = 70000.0f;  // half(70000) = inf
  rows.insert(rows.begin() + 100 * dim, far.begin(), far.end());  // row 100
  IncrementalIndex index(dim);
  Fill(index, rows, dim);
  std::vector<float> q = far;
  q[1] = 1.0f;
  const auto r = index.Search(q.data(), FrameId(0), 0);
  ASSERT_TRUE(r.best.has_value());
  EXPECT_EQ(r.best->frame, FrameId(300));  // row 100, frames are 3 apart (its model distance
                                           // cancels to 0 in float: norms of 4.9e9)
  ExpectSameAsFullScan(index, q.data(), 0, 0);
}

INSTANTIATE_TEST_SUITE_P(Widths, FastSearchByWidth, ::testing::Values(1, 3, 13, 16, 128, 130));

// The product's own row kernel (gemv_row.h), where this build has it: every row of products of
// 2 to 65 rows, 8 rows at a time and one at a time, equals Eigen's product bit for bit.
TEST(GemvRowKernel, EightRowsAndOneRowEqualTheFullProductBitForBit) {
  if (!GemvRowKernelMatches(2, 8)) GTEST_SKIP() << "no row kernel in this build (it needs AVX and FMA, no AVX-512)";
#if DVPR_GEMV_ROW_KERNEL
  std::mt19937 rng(5);
  for (int dim : {8, 16, 128, 256}) {
    const std::vector<float> q = Gaussian(rng, 1, dim);
    for (int rows : {2, 3, 5, 7, 8, 9, 15, 16, 17, 45, 64, 65}) {
      const std::vector<float> data = Gaussian(rng, rows, dim);
      const Eigen::VectorXf full = FullProduct(data, rows, dim, q);
      for (int first = 0; first < rows; first += 8) {
        const float* block[8];
        for (int r = 0; r < 8; ++r) block[r] = &data[static_cast<std::size_t>(std::min(first + r, rows - 1)) * dim];
        float eight[8];
        GemvEightRows(block, q.data(), dim, eight);
        for (int r = 0; r < 8 && first + r < rows; ++r) {
          const int i = first + r;
          ASSERT_EQ(std::bit_cast<std::uint32_t>(eight[r]), std::bit_cast<std::uint32_t>(full[i]))
              << "dim " << dim << " rows " << rows << " row " << i;
          ASSERT_EQ(std::bit_cast<std::uint32_t>(GemvOneRow(&data[static_cast<std::size_t>(i) * dim], q.data(), dim)),
                    std::bit_cast<std::uint32_t>(full[i]));
        }
      }
    }
  }
#endif
}

// The 16-row kernel (AVX-512, where the CPU has it): every row of products of 2 to 65 rows,
// 16 rows at a time, equals Eigen's product of the x86-64-v3 build bit for bit, and so the
// 8-row kernel's value.
TEST(GemvRowKernel, SixteenRowsEqualTheFullProductBitForBit) {
  if (!GemvRowKernelMatches(2, 8)) GTEST_SKIP() << "no row kernel in this build";
#if DVPR_GEMV_ROW_KERNEL
  if (!HasGemvSixteenRows()) GTEST_SKIP() << "this CPU has no AVX-512";
  std::mt19937 rng(6);
  for (int dim : {8, 16, 128, 256}) {
    const std::vector<float> q = Gaussian(rng, 1, dim);
    for (int rows : {2, 3, 9, 15, 16, 17, 31, 33, 45, 64, 65}) {
      const std::vector<float> data = Gaussian(rng, rows, dim);
      const Eigen::VectorXf full = FullProduct(data, rows, dim, q);
      for (int first = 0; first < rows; first += 16) {
        const float* block[16];
        for (int r = 0; r < 16; ++r) block[r] = &data[static_cast<std::size_t>(std::min(first + r, rows - 1)) * dim];
        float sixteen[16];
        GemvSixteenRows(block, q.data(), dim, sixteen);
        for (int r = 0; r < 16 && first + r < rows; ++r) {
          ASSERT_EQ(std::bit_cast<std::uint32_t>(sixteen[r]), std::bit_cast<std::uint32_t>(full[first + r]))
              << "dim " << dim << " rows " << rows << " row " << first + r;
        }
      }
    }
  }
  // The reduction's order in both halves: 2^24 + 1 rounds away in (l0 + l4) first (see below),
  // so each row of ones-weighted lanes {2^24, 0, -2^24, 0, 1, 0, 1, 0} sums to 1, not 2.
  const float big = 16777216.0f;
  const std::vector<float> row = {big, 0, -big, 0, 1, 0, 1, 0};
  const std::vector<float> ones(8, 1.0f);
  const float* block[16];
  for (auto& b : block) b = row.data();
  float sixteen[16];
  GemvSixteenRows(block, ones.data(), 8, sixteen);
  for (const float v : sixteen) EXPECT_EQ(v, 1.0f);
#endif
}

TEST(GemvRowKernel, AddsALanesSumsInThePacketReductionsOrder) {
  // One packet of 8 products 2^24, 0, -2^24, 0, 1, 0, 1, 0 (query of ones). Eigen's reduction
  // adds (l0 + l4) + (l2 + l6) first: 2^24 + 1 rounds to 2^24 (ties to even), -2^24 + 1 is
  // exact, their sum is 1; the other lanes add 0. Left to right the sum would be 2.
  if (!GemvRowKernelMatches(2, 8)) GTEST_SKIP() << "no row kernel in this build";
#if DVPR_GEMV_ROW_KERNEL
  const float big = 16777216.0f;
  const std::vector<float> rows = {big, 0, -big, 0, 1, 0, 1, 0, big, 0, -big, 0, 1, 0, 1, 0};
  const std::vector<float> q(8, 1.0f);
  EXPECT_EQ(GemvOneRow(rows.data(), q.data(), 8), 1.0f);
  EXPECT_EQ(GemvRowAsInFullProduct(rows.data(), 2, 8, 1, q.data()), 1.0f);
#endif
  EXPECT_FALSE(GemvRowKernelMatches(1, 128));  // a 1-row product is Eigen's dot product
  EXPECT_FALSE(GemvRowKernelMatches(2, 130));  // a width's tail takes other paths
}

// Stores of up to 64 rows are searched by reading every row (SearchEveryRow) where the build has
// the row kernel: the same answers as the full scan, bit for bit, at every store size, with
// ties, near ties and windows; widths without the kernel take the staged search.
class SmallStoreSearch : public ::testing::TestWithParam<int> {};

TEST_P(SmallStoreSearch, EveryStoreSizeUpTo70MatchesFullScanAndBruteForce) {
  const int dim = GetParam();
  std::mt19937 rng(static_cast<unsigned>(300 + dim));
  const std::vector<float> gaussian = Gaussian(rng, 70, dim), integers = Integers(rng, 70, dim, 1);
  const std::vector<float> queries = Gaussian(rng, 8, dim), int_queries = Integers(rng, 8, dim, 1);
  for (const auto* rows : {&gaussian, &integers}) {
    IncrementalIndex index(dim);
    Stored s{dim, {}, {}};
    for (int n = 1; n <= 70; ++n) {
      s.rows.insert(s.rows.end(), rows->begin() + static_cast<std::ptrdiff_t>((n - 1) * dim),
                    rows->begin() + static_cast<std::ptrdiff_t>(n * dim));
      s.frames.push_back((n - 1) * 3);
      index.Add(RobotId(n % 7), FrameId(s.frames.back()), &(*rows)[static_cast<std::size_t>((n - 1) * dim)]);
      const auto& qs = rows == &integers ? int_queries : queries;
      for (int k = 0; k < 8; ++k) {
        const float* q = &qs[static_cast<std::size_t>(k) * dim];
        for (int window : {0, 10, 500}) {
          const int frame = k * 25;
          ExpectSameAsFullScan(index, q, frame, window);
          const auto expected = BruteForce(s, q, frame, window);
          const auto r = index.Search(q, FrameId(frame), window);
          ASSERT_EQ(r.best.has_value(), expected.has_value()) << "n " << n << " query " << k;
          if (rows == &integers && expected) {  // exact arithmetic: the same row, ties to the first
            EXPECT_EQ(r.best->frame, FrameId(s.frames[*expected])) << "n " << n << " query " << k;
          }
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Widths, SmallStoreSearch, ::testing::Values(8, 13, 128));

TEST(FastSearch, APreviousWinnerLaterInTheStoreLosesATieToAnEarlierEntry) {
  // Rows 0 and 2 are the same point. The first query cannot see row 0 (window), so row 2 wins
  // and becomes the search's first guess; the second query sees both: the tie goes to row 0.
  IncrementalIndex index(2);
  const float a[2] = {1.0f, 2.0f}, far[2] = {50.0f, 50.0f};
  index.Add(RobotId(0), FrameId(0), a);
  index.Add(RobotId(1), FrameId(100), far);
  index.Add(RobotId(2), FrameId(200), a);
  const float q[2] = {1.5f, 2.0f};
  auto r = index.Search(q, FrameId(10), 20);
  ASSERT_TRUE(r.best.has_value());
  EXPECT_EQ(r.best->frame, FrameId(200));
  r = index.Search(q, FrameId(1000), 20);
  ASSERT_TRUE(r.best.has_value());
  EXPECT_EQ(r.best->frame, FrameId(0));
  EXPECT_EQ(r.best->distance, 0.25f);
}

TEST(FastSearch, APreviousWinnerInsideTheNextWindowIsNotReturned) {
  IncrementalIndex index(1);
  const float x0 = 0.0f, x1 = 10.0f;
  index.Add(RobotId(0), FrameId(0), &x0);
  index.Add(RobotId(1), FrameId(500), &x1);
  const float q = 0.0f;
  EXPECT_EQ(index.Search(&q, FrameId(1000), 10).best->frame, FrameId(0));
  const auto r = index.Search(&q, FrameId(5), 10);  // frame 0 now suppressed
  ASSERT_TRUE(r.best.has_value());
  EXPECT_EQ(r.best->frame, FrameId(500));
  EXPECT_EQ(r.best->distance, 100.0f);
}

}  // namespace
}  // namespace dvpr
