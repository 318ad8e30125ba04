#include "sim/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

namespace dvpr {
namespace {

// Outputs of the reference xoshiro256** (prng.di.unimi.it) from state {1, 2, 3, 4}.
// The first two are easy to check by hand: rotl(2 * 5, 7) * 9 = 1280 * 9 = 11520;
// after one step s[1] = 2 ^ (3 ^ 1) = 0, so the second output is 0.
TEST(RandomStream, MatchesReferenceXoshiro256StarStar) {
  RandomStream r = RandomStream::FromState(1, 2, 3, 4);
  EXPECT_EQ(r.NextU64(), 11520u);
  EXPECT_EQ(r.NextU64(), 0u);
  EXPECT_EQ(r.NextU64(), 1509978240u);
  EXPECT_EQ(r.NextU64(), 1215971899390074240u);
}

TEST(RandomStream, SameSeedAndComponentGiveTheSameStream) {
  RandomStream a(42, ComponentId("robot/3"));
  RandomStream b(42, ComponentId("robot/3"));
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(a.NextU64(), b.NextU64());
}

TEST(RandomStream, DifferentComponentsOrSeedsDiffer) {
  RandomStream a(42, 0), b(42, 1), c(43, 0);
  int same_ab = 0, same_ac = 0;
  for (int i = 0; i < 1000; ++i) {
    const auto x = a.NextU64();
    same_ab += x == b.NextU64();
    same_ac += x == c.NextU64();
  }
  EXPECT_EQ(same_ab, 0);
  EXPECT_EQ(same_ac, 0);
}

TEST(RandomStream, ComponentIdIsFnv1a) {
  // FNV-1a 64 of "" is the offset basis; of "a" it is 0xaf63dc4c8601ec8c (published test vector).
  EXPECT_EQ(ComponentId(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(ComponentId("a"), 0xaf63dc4c8601ec8cULL);
}

TEST(RandomStream, Uniform01IsInRangeWithMeanOneHalf) {
  RandomStream r(7, 7);
  constexpr int kN = 100000;
  double sum = 0;
  for (int i = 0; i < kN; ++i) {
    const double u = r.Uniform01();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
  }
  // Var(U) = 1/12; the mean's standard error is sqrt(1/12/kN) ~ 0.000913; allow 4 sigma.
  EXPECT_NEAR(sum / kN, 0.5, 4 * std::sqrt(1.0 / 12 / kN));
}

TEST(RandomStream, UniformIntCoversTheRangeEvenly) {
  RandomStream r(1, 2);
  int counts[6] = {};
  constexpr int kN = 60000;
  for (int i = 0; i < kN; ++i) ++counts[r.UniformInt(6)];
  // Binomial(60000, 1/6): sd = sqrt(60000 * 1/6 * 5/6) ~ 91.3; allow 4 sigma.
  for (int c : counts) EXPECT_NEAR(c, 10000, 4 * 91.3);
}

TEST(RandomStream, BernoulliExtremes) {
  RandomStream r(1, 2);
  for (int i = 0; i < 100; ++i) {
    EXPECT_FALSE(r.Bernoulli(0.0));
    EXPECT_TRUE(r.Bernoulli(1.0));
  }
}

}  // namespace
}  // namespace dvpr
