// The checked SimTime arithmetic at the edges of int64 nanoseconds (worked by hand:
// int64 max = 9'223'372'036'854'775'807 ns, about 2'562'047.79 h).
#include "sim/sim_time.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

namespace dvpr {
namespace {

constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kHourNs = 3'600'000'000'000;

TEST(SimTimeChecked, AddUpToTheLargestTimeAndNoFurther) {
  EXPECT_EQ(CheckedAdd(SimTime::Nanos(kMax - 1), SimTime::Nanos(1)), SimTime::Nanos(kMax));
  EXPECT_EQ(CheckedAdd(SimTime::Nanos(kMax - 1), SimTime::Nanos(2)), std::nullopt);
  EXPECT_EQ(CheckedAdd(SimTime::Nanos(kMin), SimTime::Nanos(-1)), std::nullopt);
  EXPECT_EQ(CheckedAdd(SimTime::Millis(2), SimTime::Micros(50)), SimTime::Nanos(2'050'000));
}

TEST(SimTimeChecked, TwoOfTheLargestWholeHoursOverflow) {
  // 2'562'047 h = 9'223'369'200'000'000'000 ns fits; twice that does not (the case).
  const SimTime h = SimTime::Nanos(kHourNs);
  EXPECT_EQ(CheckedMul(h, 2'562'047), SimTime::Nanos(9'223'369'200'000'000'000));
  EXPECT_EQ(CheckedMul(h, 2'562'048), std::nullopt);  // 9'223'372'800'000'000'000 > max
  EXPECT_EQ(CheckedAdd(*CheckedMul(h, 2'562'047), *CheckedMul(h, 2'562'047)), std::nullopt);
  EXPECT_EQ(CheckedMul(SimTime::Nanos(20), 4541), SimTime::Nanos(90'820));
  EXPECT_EQ(CheckedMul(SimTime::Nanos(-1), kMin), std::nullopt);
}

TEST(SimTimeChecked, SecondsFromADouble) {
  EXPECT_EQ(CheckedSeconds(1.5), SimTime::Millis(1500));
  EXPECT_EQ(CheckedSeconds(0.1), SimTime::Millis(100));
  // 9.2e9 s = 9.2e18 ns fits; 9.3e9 s does not; 1e-9 fps gives a frame every 1e9 s, and frame 10
  // is at 1e10 s.
  EXPECT_EQ(CheckedSeconds(9.2e9), SimTime::Nanos(9'200'000'000'000'000'000));
  EXPECT_EQ(CheckedSeconds(9.3e9), std::nullopt);
  EXPECT_EQ(CheckedSeconds(1e10), std::nullopt);
  EXPECT_EQ(CheckedSeconds(-9.3e9), std::nullopt);
  EXPECT_EQ(CheckedSeconds(std::nan("")), std::nullopt);
  EXPECT_EQ(CheckedSeconds(std::numeric_limits<double>::infinity()), std::nullopt);
}

}  // namespace
}  // namespace dvpr
