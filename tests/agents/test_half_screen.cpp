// The half-precision screen (agents/algorithms/half_screen.h): its bounds never rule out a row that lies
// within the given exact distance, its sums are those worked out by hand, and values a half
// cannot hold switch the bound off instead of breaking it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "agents/algorithms/half_screen.h"

namespace dvpr {
namespace {

std::vector<float> Rows(std::mt19937& rng, int count, int dim, float scale) {
  std::normal_distribution<float> normal(0.0f, 1.0f);
  std::vector<float> v(static_cast<std::size_t>(count) * dim);
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < dim; ++j) v[static_cast<std::size_t>(i) * dim + j] = scale * normal(rng) / std::sqrt(j + 1.0f);
  }
  return v;
}

double ExactSquared(const float* a, const float* b, int dim) {
  double sum = 0.0;
  for (int j = 0; j < dim; ++j) sum += (double{a[j]} - double{b[j]}) * (double{a[j]} - double{b[j]});
  return sum;
}

// Bit r of each tile, as one flag a row.
std::vector<bool> AllSurvivors(const HalfScreen& screen, const float* query, const std::vector<float>& limits) {
  std::vector<bool> alive;
  for (std::size_t first = 0; first < screen.size(); first += HalfScreen::kTileRows) {
    const unsigned bits = screen.Survivors(first, query, limits.data());
    for (std::size_t r = 0; r < HalfScreen::kTileRows && first + r < screen.size(); ++r) alive.push_back((bits >> r & 1u) != 0);
  }
  return alive;
}

TEST(HalfScreen, ChecksAfter32ValuesThenEvery16AndAtDim) {
  EXPECT_EQ(HalfScreen(128).checks(), (std::vector<int>{32, 48, 64, 80, 96, 112, 128}));
  EXPECT_EQ(HalfScreen(40).checks(), (std::vector<int>{32, 40}));
  EXPECT_EQ(HalfScreen(32).checks(), (std::vector<int>{32}));
  EXPECT_EQ(HalfScreen(5).checks(), (std::vector<int>{5}));
}

TEST(HalfScreen, NeverRulesOutARowWithinTheExactDistance) {
  // Rows near the query (a copy nudged below half precision's resolution) and far ones; the
  // exact radius is each row's own distance in turn, so rows sit right on the boundary.
  for (int dim : {5, 32, 45, 128}) {
    std::mt19937 rng(static_cast<unsigned>(dim));
    std::vector<float> rows = Rows(rng, 61, dim, 1.0f);
    const std::vector<float> query = Rows(rng, 1, dim, 1.0f);
    std::uniform_real_distribution<float> nudge(-4e-4f, 4e-4f);
    for (int i = 0; i < 40; ++i) {
      for (int j = 0; j < dim; ++j) rows.push_back(query[static_cast<std::size_t>(j)] + nudge(rng));
    }
    HalfScreen screen(dim);
    const int count = static_cast<int>(rows.size()) / dim;
    for (int i = 0; i < count; ++i) screen.Append(&rows[static_cast<std::size_t>(i) * dim]);
    ASSERT_EQ(screen.size(), static_cast<std::size_t>(count));
    int ruled_out = 0;
    for (int r = 0; r < count; r += 3) {
      const double radius = ExactSquared(&rows[static_cast<std::size_t>(r) * dim], query.data(), dim);
      std::vector<float> limits(screen.checks().size());
      for (std::size_t k = 0; k < limits.size(); ++k) limits[k] = screen.Limit(radius, k);
      const std::vector<bool> alive = AllSurvivors(screen, query.data(), limits);
      for (int i = 0; i < count; ++i) {
        const double d = ExactSquared(&rows[static_cast<std::size_t>(i) * dim], query.data(), dim);
        if (d <= radius) {
          EXPECT_TRUE(alive[static_cast<std::size_t>(i)]) << "dim " << dim << " radius of row " << r << ", row " << i;
        }
        ruled_out += alive[static_cast<std::size_t>(i)] ? 0 : 1;
      }
    }
    EXPECT_GT(ruled_out, 0) << "dim " << dim << ": the screen ruled nothing out";
  }
}

TEST(HalfScreen, FirstBandSumsAreTheSquaredDifferencesOfTheHalves) {
  // Values exactly representable in half precision: the sums are exact, worked out by hand.
  // Row r holds r + 0.5 in every value; the query holds 1 in every value; width 3 (one band).
  HalfScreen screen(3);
  for (int r = 0; r < 10; ++r) {
    const float v = static_cast<float>(r) + 0.5f;
    const float row[3] = {v, v, v};
    screen.Append(row);
  }
  const float query[3] = {1.0f, 1.0f, 1.0f};
  float sums[8];
  screen.FirstBandSums(0, query, sums);
  // 3 x (r - 0.5)^2 for rows 0..7: 0.75, 0.75, 6.75, 18.75, 36.75, 60.75, 90.75, 126.75
  const float expected[8] = {0.75f, 0.75f, 6.75f, 18.75f, 36.75f, 60.75f, 90.75f, 126.75f};
  for (int r = 0; r < 8; ++r) EXPECT_EQ(sums[r], expected[r]) << r;
  screen.FirstBandSums(8, query, sums);  // rows 8, 9, then padding (zeros: 3 x 1)
  EXPECT_EQ(sums[0], 3.0f * 7.5f * 7.5f);
  EXPECT_EQ(sums[1], 3.0f * 8.5f * 8.5f);
  EXPECT_EQ(sums[2], 3.0f);
  // These values are exact halves: no rounding error, so the limit for radius 0.75 is 0.75
  // widened only by the float sum's allowance (4 x 6 units of 2^-24) and one float step.
  EXPECT_GE(screen.Limit(0.75, 0), 0.75f);
  EXPECT_LT(screen.Limit(0.75, 0), 0.75f * (1.0f + 1e-5f));
  const float limit[1] = {screen.Limit(0.75, 0)};
  EXPECT_EQ(screen.Survivors(0, query, limit), 0b11u);  // rows 0 and 1
}

TEST(HalfScreen, ValuesBeyondHalfRangeSwitchTheBoundOff) {
  HalfScreen screen(4);
  const float ordinary[4] = {0.1f, 0.2f, 0.3f, 0.4f};
  screen.Append(ordinary);
  EXPECT_TRUE(std::isfinite(screen.Limit(1.0, 0)));
  const float huge[4] = {70000.0f, 0.0f, 0.0f, 0.0f};  // above 65504, the largest finite half
  screen.Append(huge);
  EXPECT_EQ(screen.Limit(1.0, 0), std::numeric_limits<float>::infinity());
  const float query[4] = {70000.0f, 0.0f, 0.0f, 0.0f};
  const float limits[1] = {screen.Limit(0.0, 0)};
  EXPECT_EQ(screen.Survivors(0, query, limits) & 0b11u, 0b11u);  // nothing ruled out
  screen.Clear();
  EXPECT_EQ(screen.size(), 0u);
  screen.Append(ordinary);
  EXPECT_TRUE(std::isfinite(screen.Limit(1.0, 0)));  // Clear forgets the error
}

TEST(HalfScreen, ANanSumRulesNothingOut) {
  HalfScreen screen(2);
  const float row[2] = {1.0f, 2.0f};
  screen.Append(row);
  const float query[2] = {std::numeric_limits<float>::quiet_NaN(), 0.0f};
  const float limits[1] = {0.0f};
  EXPECT_EQ(screen.Survivors(0, query, limits) & 1u, 1u);
}

}  // namespace
}  // namespace dvpr
