// The one-byte screen (agents/byte_screen.h): its bounds never rule out a row within the given
// exact distance (also for values it clips), its sums are those worked out by hand, its step is
// the power of two the header promises, and values it cannot hold switch the bound off.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "agents/byte_screen.h"

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

std::vector<bool> AllSurvivors(const ByteScreen& screen, const float* query, const std::vector<float>& limits) {
  std::vector<bool> alive;
  for (std::size_t first = 0; first < screen.size(); first += ByteScreen::kTileRows) {
    const unsigned bits = screen.Survivors(first, query, limits.data());
    for (std::size_t r = 0; r < ByteScreen::kTileRows && first + r < screen.size(); ++r) alive.push_back((bits >> r & 1u) != 0);
  }
  return alive;
}

TEST(ByteScreen, ChecksAfter32ValuesThenEvery16AndAtDim) {
  EXPECT_EQ(ByteScreen(128).checks(), (std::vector<int>{32, 48, 64, 80, 96, 112, 128}));
  EXPECT_EQ(ByteScreen(40).checks(), (std::vector<int>{32, 40}));
  EXPECT_EQ(ByteScreen(5).checks(), (std::vector<int>{5}));
}

TEST(ByteScreen, StepIsThePowerOfTwoThatHoldsTwiceTheFirstRowIn127Steps) {
  ByteScreen a(3);
  const float first[3] = {0.3f, -0.45f, 0.1f};  // 2 x 0.45 / 127 = 0.00709 in [2^-8, 2^-7)
  a.Append(first);
  EXPECT_EQ(a.step(), 0x1.0p-7f);
  ByteScreen b(2);
  const float big[2] = {-100.0f, 3.0f};  // 200 / 127 = 1.57 in [1, 2)
  b.Append(big);
  EXPECT_EQ(b.step(), 2.0f);
  ByteScreen c(2);
  const float zeros[2] = {0.0f, 0.0f};
  c.Append(zeros);
  EXPECT_EQ(c.step(), 0x1.0p-7f);
  c.Clear();
  EXPECT_EQ(c.step(), 0.0f);
}

TEST(ByteScreen, NeverRulesOutARowWithinTheExactDistance) {
  // Rows near the query (nudged below the step), far ones, and rows 40 times larger than the
  // first (clipped: large errors); the exact radius is each row's own distance in turn.
  for (int dim : {5, 32, 45, 128}) {
    std::mt19937 rng(static_cast<unsigned>(dim) + 7u);
    std::vector<float> rows = Rows(rng, 61, dim, 1.0f);
    const std::vector<float> query = Rows(rng, 1, dim, 1.0f);
    std::uniform_real_distribution<float> nudge(-4e-3f, 4e-3f);
    for (int i = 0; i < 40; ++i) {
      for (int j = 0; j < dim; ++j) rows.push_back(query[static_cast<std::size_t>(j)] + nudge(rng));
    }
    const int ordinary = static_cast<int>(rows.size()) / dim;
    ByteScreen screen(dim);
    for (int i = 0; i < ordinary; ++i) screen.Append(&rows[static_cast<std::size_t>(i) * dim]);
    std::vector<bool> ruled_out_before_clipping;
    for (int pass = 0; pass < 2; ++pass) {
      const int count = static_cast<int>(rows.size()) / dim;
      ASSERT_EQ(screen.size(), static_cast<std::size_t>(count));
      int ruled_out = 0;
      for (int r = 0; r < count; r += 3) {
        const double radius = ExactSquared(&rows[static_cast<std::size_t>(r) * dim], query.data(), dim);
        std::vector<float> limits(screen.checks().size());
        for (std::size_t k = 0; k < limits.size(); ++k) limits[k] = screen.Limit(radius, k);
        const std::vector<bool> alive = AllSurvivors(screen, query.data(), limits);
        for (int i = 0; i < count; ++i) {
          const double d = ExactSquared(&rows[static_cast<std::size_t>(i) * dim], query.data(), dim);
          if (d <= radius) EXPECT_TRUE(alive[static_cast<std::size_t>(i)]) << "dim " << dim << " pass " << pass << " row " << i;
          ruled_out += alive[static_cast<std::size_t>(i)] ? 0 : 1;
        }
      }
      if (pass == 0) EXPECT_GT(ruled_out, 0) << "dim " << dim << ": the screen ruled nothing out";
      const std::vector<float> large = Rows(rng, 3, dim, 40.0f);  // clipped at 127 steps
      for (int i = 0; i < 3; ++i) screen.Append(&large[static_cast<std::size_t>(i) * dim]);
      rows.insert(rows.end(), large.begin(), large.end());
    }
  }
}

TEST(ByteScreen, SumsAreTheSquaredDifferencesOfTheCopies) {
  // First row 1.0: 2/127 = 0.0157 -> step 2^-5. Rows hold multiples of 2^-5 (exact copies: no error);
  // query 0.5 everywhere, width 3 (one band). Row r: 3 x (r/8 - 0.5)^2, worked out by hand.
  ByteScreen screen(3);
  for (int r = 0; r < 10; ++r) {
    const float v = r == 0 ? 1.0f : static_cast<float>(r) / 8.0f;
    const float row[3] = {v, v, v};
    screen.Append(row);
  }
  ASSERT_EQ(screen.step(), 0x1.0p-5f);
  const float query[3] = {0.5f, 0.5f, 0.5f};
  // Rows 0..7: 0.75, 3 x 0.375^2 = 0.421875, 0.1875, 0.046875, 0, 0.046875, 0.1875, 0.421875.
  // No error and exact sums: the limit for 0.1875 keeps rows 2..6 (and nothing above 0.1875).
  const float limit[1] = {screen.Limit(0.1875, 0)};
  EXPECT_GE(limit[0], 0.1875f);
  EXPECT_LT(limit[0], 0.1875f * (1.0f + 1e-5f));
  EXPECT_EQ(screen.Survivors(0, query, limit), 0b01111100u);
  // Rows 8, 9 (1.0, 1.125: 0.75, 1.171875), then padding (zeros: 0.75).
  const float wide[1] = {screen.Limit(0.75, 0)};
  EXPECT_EQ(screen.Survivors(8, query, wide), 0b11111101u);
}

TEST(ByteScreen, ValuesNotFiniteSwitchTheBoundOff) {
  ByteScreen screen(4);
  const float ordinary[4] = {0.1f, 0.2f, 0.3f, 0.4f};
  screen.Append(ordinary);
  EXPECT_TRUE(std::isfinite(screen.Limit(1.0, 0)));
  const float bad[4] = {std::numeric_limits<float>::quiet_NaN(), 0.0f, 0.0f, 0.0f};
  screen.Append(bad);
  EXPECT_EQ(screen.Limit(1.0, 0), std::numeric_limits<float>::infinity());
  const float query[4] = {5.0f, 5.0f, 5.0f, 5.0f};
  const float limits[1] = {screen.Limit(0.0, 0)};
  EXPECT_EQ(screen.Survivors(0, query, limits) & 0b11u, 0b11u);  // nothing ruled out
  ByteScreen infinite(2);
  const float inf[2] = {std::numeric_limits<float>::infinity(), 0.0f};
  infinite.Append(ordinary);
  infinite.Append(inf);
  EXPECT_EQ(infinite.Limit(1.0, 0), std::numeric_limits<float>::infinity());
}

}  // namespace
}  // namespace dvpr
