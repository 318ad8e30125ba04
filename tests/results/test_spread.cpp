// The spread beside each mean (experiments/results/spread.h): the sample standard deviation and
// the 95 % confidence interval's half-width t(0.975, n - 1) s / sqrt(n), worked by hand with
// Student's t from a printed table (3 df: 3.182446305; 1 df: 12.706204736; 9 df: 2.262157163).
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "experiments/results/spread.h"

namespace dvpr {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(Spread, FourRunsGiveTheHandWorkedTInterval) {
  // 1, 2, 3, 4: mean 2.5; squares 2.25 + 0.25 + 0.25 + 2.25 = 5, s = sqrt(5 / 3) = 1.2909944487;
  // half-width 3.182446305 x 1.2909944487 / 2 = 2.0542602568.
  const std::vector<double> v = {1, 2, 3, 4};
  const Spread s = SpreadOf(v);
  EXPECT_EQ(s.n, 4);
  EXPECT_EQ(s.mean, 2.5);
  EXPECT_NEAR(s.std, 1.2909944487, 1e-9);
  EXPECT_NEAR(s.ci95, 2.0542602568, 1e-9);
}

TEST(Spread, TwoRunsUseTheWideT) {
  // 0.8, 0.9: s = 0.0707106781; half-width 12.706204736 x 0.0707106781 / sqrt(2) = 0.6353102368.
  const std::vector<double> v = {0.8, kNaN, 0.9};  // a run without the metric is left out
  const Spread s = SpreadOf(v);
  EXPECT_EQ(s.n, 2);
  EXPECT_NEAR(s.mean, 0.85, 1e-15);
  EXPECT_NEAR(s.std, 0.0707106781, 1e-9);
  EXPECT_NEAR(s.ci95, 0.6353102368, 1e-9);
}

TEST(Spread, StudentsTQuantilesAreTheTables) {
  EXPECT_NEAR(StudentT975(1), 12.706204736, 1e-8);
  EXPECT_NEAR(StudentT975(3), 3.182446305, 1e-8);
  EXPECT_NEAR(StudentT975(9), 2.262157163, 1e-8);
  EXPECT_NEAR(StudentT975(1000), 1.962339, 1e-6);  // close to the normal 1.96
  EXPECT_THROW(StudentT975(0), std::invalid_argument);
}

TEST(Spread, BelowTwoValuesThereIsNoSpread) {
  const Spread one = SpreadOf(std::vector<double>{0.7});
  EXPECT_EQ(one.n, 1);
  EXPECT_EQ(one.mean, 0.7);
  EXPECT_TRUE(std::isnan(one.std));
  EXPECT_TRUE(std::isnan(one.ci95));
  const Spread none = SpreadOf(std::vector<double>{kNaN});
  EXPECT_EQ(none.n, 0);
  EXPECT_TRUE(std::isnan(none.mean));
  // Identical runs: no spread at all.
  const Spread same = SpreadOf(std::vector<double>{3, 3, 3});
  EXPECT_EQ(same.std, 0.0);
  EXPECT_EQ(same.ci95, 0.0);
}

}  // namespace
}  // namespace dvpr
