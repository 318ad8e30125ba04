// The config's start_time: virtual time 0 of a simulated run as a UTC instant, held as
// microseconds since the Unix epoch (the unit of LCM's utime). Expected values from python3:
// int(datetime(Y, M, D, h, m, s, tzinfo=timezone.utc).timestamp()) * 10**6 + microseconds.
#include <string>

#include <gtest/gtest.h>

#include "experiments/config/config.h"
#include "tests/config/config_test_support.h"
#include "experiments/config/utc_instant.h"

namespace dvpr {
namespace {

using testing_support::ErrorOf;
using testing_support::Parse;

TEST(StartTime, DefaultsToAFixedInstantNotTheWallClock) {
  EXPECT_EQ(Parse("name: x\n").start_utime, 1317643200000000);  // 2011-10-03T12:00:00Z
  EXPECT_EQ(kDefaultStartUtime, 1317643200000000);
}

TEST(StartTime, ReadsAUtcInstantWithOrWithoutFraction) {
  EXPECT_EQ(Parse("start_time: 2024-02-29T23:59:59Z\n").start_utime, 1709251199000000);
  EXPECT_EQ(Parse("start_time: 1970-01-01T00:00:00.5Z\n").start_utime, 500000);
  EXPECT_EQ(Parse("start_time: 2011-10-03T12:00:00.000001Z\n").start_utime, 1317643200000001);
  EXPECT_EQ(Parse("start_time: 9999-12-31T23:59:59.999999Z\n").start_utime, 253402300799999999);
}

TEST(StartTime, RejectsOtherFormsNamingTheKeyAndValue) {
  const std::string range = "in [1970-01-01T00:00:00Z, 9999-12-31T23:59:59.999999Z], got ";
  EXPECT_EQ(ErrorOf("start_time: 2011-02-29T00:00:00Z\n"),
            "test.yaml: start_time: expected a UTC instant YYYY-MM-DDTHH:MM:SS[.ffffff]Z " + range +
                "'2011-02-29T00:00:00Z'");
  for (const std::string bad : {"2011-10-03 12:00:00", "2011-10-03T12:00:00+02:00", "2011-10-03", "1317643200",
                                "1969-12-31T23:59:59Z", "2011-10-03T24:00:00Z", "2011-10-03T12:00:60Z",
                                "2011-10-03T12:00:00.Z", "2011-10-03T12:00:00.1234567Z", "2011-1O-03T12:00:00Z"}) {
    EXPECT_NE(ErrorOf("start_time: '" + bad + "'\n").find("start_time: expected a UTC instant"), std::string::npos)
        << bad;
  }
}

TEST(StartTime, FormatReadsBackUnchanged) {
  EXPECT_EQ(FormatUtcInstant(1317643200000000), "2011-10-03T12:00:00Z");
  EXPECT_EQ(FormatUtcInstant(500000), "1970-01-01T00:00:00.5Z");
  EXPECT_EQ(FormatUtcInstant(1709251199000123), "2024-02-29T23:59:59.000123Z");
  EXPECT_EQ(FormatUtcInstant(kMaxUtcInstant), "9999-12-31T23:59:59.999999Z");
  for (const std::int64_t t : {std::int64_t{0}, std::int64_t{1}, std::int64_t{1317643200000001}, kMaxUtcInstant}) {
    EXPECT_EQ(ParseUtcInstant(FormatUtcInstant(t)), t);
  }
  // The resolved config writes it, and reading that back gives the same instant.
  const ExperimentConfig c = Parse("start_time: 2024-02-29T23:59:59.25Z\n");
  EXPECT_NE(EmitConfig(c).find("start_time: 2024-02-29T23:59:59.25Z\n"), std::string::npos) << EmitConfig(c);
}

}  // namespace
}  // namespace dvpr
